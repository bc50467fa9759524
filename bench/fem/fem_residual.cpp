// The elastic internal force on the paper mesh: the specialised kernel (one precomputed 24x24
// box-cell stiffness scaled by E, one per cell shape on an edge-graded mesh) against PETSc's generic PetscFE residual
// (DMPlexTSComputeRHSFunctionFEM), and the whole right-hand side of one explicit step.
// Prints the specialised/generic ratio at the end of the run. Scene from gradfric-fem's options
// (mesh by -fem_nx/-fem_ny/-fem_nz), read and checked as the driver does.
#include <petscsection.h>
#include <petscsf.h>

#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"

#include <benchmark/benchmark.h>
#include <petscsys.h>

#include <array>
#include <cstdio>
#include <vector>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace {

using namespace gradfric;
using namespace gradfric::fem;

std::unique_ptr<PlateModel> gModel;  // built in main from gradfric-fem's options, before any benchmark
std::map<std::string, double> gSecondsPerCall;

PlateModel& model() { return *gModel; }

template <typename Call>
void timeCalls(benchmark::State& state, const char* name, Call call) {
  double total = 0;
  long calls = 0;
  for (auto _ : state) {
    MPI_Barrier(PETSC_COMM_WORLD);
    const double t0 = MPI_Wtime();
    call();
    MPI_Barrier(PETSC_COMM_WORLD);
    double dt = MPI_Wtime() - t0;
    // Every rank must see the same time, or Google Benchmark picks different iteration counts
    // on different ranks and the collective calls deadlock.
    MPI_Bcast(&dt, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
    state.SetIterationTime(dt);
    total += dt;
    ++calls;
  }
  gSecondsPerCall[name] = total / calls;
  state.counters["cells"] = static_cast<double>(model().mesh().globalCells());
  state.counters["ns_per_cell"] = 1e9 * total / calls / model().mesh().globalCells();
}

void BM_ElasticSpecialised(benchmark::State& state) {
  PlateModel& m = model();
  OwnedVec u, f;
  DMCreateGlobalVector(m.elastic().displacementDM(), u.out());
  VecDuplicate(u, f.out());
  VecSet(u, 1e-9);
  timeCalls(state, "specialised", [&] { m.elastic().forceSpecialised(u, f); });
}

void BM_ElasticGeneric(benchmark::State& state) {
  PlateModel& m = model();
  OwnedVec u, f;
  DMCreateGlobalVector(m.elastic().displacementDM(), u.out());
  VecDuplicate(u, f.out());
  VecSet(u, 1e-9);
  timeCalls(state, "generic", [&] { m.elastic().forceGeneric(u, f); });
}

void BM_WholeRightHandSide(benchmark::State& state) {
  PlateModel& m = model();
  OwnedVec X(m.createState()), F;
  VecDuplicate(X, F.out());
  timeCalls(state, "rhs", [&] { m.rhs(0.0, X, F); });
}

// The cell kernel alone on this rank's cells (no ghost exchange): the dense 24x24 product against
// the mirror-basis blocks (elastic_kernel.cpp), same input, in one run: their ratio is load-free.
// PerCellShape: each cell's own stiffness or blocks (an edge-graded mesh, -fem_edge_ratio), against
// the first shape's for every cell on the same cells: the cost of the shape table.
template <bool Blocked, bool PerCellShape = false>
void kernelOnly(benchmark::State& state, const char* name) {
  PlateModel& m = model();
  OwnedVec xLocal;
  DMCreateLocalVector(m.dm(), xLocal.out());
  VecSet(xLocal, 1e-9);
  PetscInt n = 0;
  VecGetLocalSize(xLocal, &n);
  std::vector<double> f(n, 0.0);
  std::vector<double> blocks, stiffnesses;  // per shape: 72 and 576 values
  for (const BoxElement& e : m.elastic().elements()) {
    std::array<double, 72> b{};
    reflectionBlocks(e.stiffness.data(), &b);
    blocks.insert(blocks.end(), b.begin(), b.end());
    stiffnesses.insert(stiffnesses.end(), e.stiffness.begin(), e.stiffness.end());
  }
  const int* shape = PerCellShape ? m.mesh().cellShape().data() : nullptr;
  const PetscScalar* x = nullptr;
  VecGetArrayRead(xLocal, &x);
  const std::vector<PetscInt>& off = m.mesh().cellStateOffsets();
  const PetscInt cells = m.mesh().localCells();
  timeCalls(state, name, [&] {
    if (Blocked)
      elasticKernelBlocked(cells, off.data(), m.elastic().cellModulus().data(), blocks.data(), x, f.data(), nullptr,
                           shape);
    else
      elasticKernel(cells, off.data(), m.elastic().cellModulus().data(), stiffnesses.data(), x, nullptr, 0.0, f.data(),
                    nullptr, shape);
  });
  VecRestoreArrayRead(xLocal, &x);
}
void BM_KernelDense(benchmark::State& state) { kernelOnly<false>(state, "kernel dense"); }
void BM_KernelBlocked(benchmark::State& state) { kernelOnly<true>(state, "kernel blocked"); }
void BM_KernelDensePerCellShape(benchmark::State& state) { kernelOnly<false, true>(state, "kernel dense, per-cell shape"); }
void BM_KernelBlockedPerCellShape(benchmark::State& state) {
  kernelOnly<true, true>(state, "kernel blocked, per-cell shape");
}

// Ranks other than 0 run the same (collective) benchmarks silently.
class QuietReporter : public benchmark::BenchmarkReporter {
public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>&) override {}
};

BENCHMARK(BM_ElasticSpecialised)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_ElasticGeneric)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_KernelDense)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_KernelBlocked)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_KernelDensePerCellShape)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_KernelBlockedPerCellShape)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_WholeRightHandSide)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

const char help[] =
    "bench_fem_residual: the elastic internal force, specialised kernel against PetscFE's generic residual\n"
    "  (gradfric-fem's options; the plate is E-graded, -grading_profile linear -grading_delta 0.2, unless set)\n";

// A graded plate unless the user chose another: the graded stiffness path is the one timed.
void defaultToGradedPlate() {
  PetscBool set = PETSC_FALSE;
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-grading_profile", &set));
  if (set) return;
  GF_CALL(PetscOptionsSetValue(nullptr, "-grading_profile", "linear"));
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-grading_delta", &set));
  if (!set) GF_CALL(PetscOptionsSetValue(nullptr, "-grading_delta", "0.2"));
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);  // takes its --benchmark_ flags; the rest are PETSc options
  return runDriver(argc, argv, help, [](MPI_Comm comm) {
    defaultToGradedPlate();
    RunParameters record;
    std::optional<FemScene> scene = readCheckedFemScene(comm, &record);  // gradfric-fem's options and checks
    if (!scene) return;
    scene->params.verbose = false;
    gModel = std::make_unique<PlateModel>(comm, scene->params, scene->grading);
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    QuietReporter quiet;  // ranks other than 0 run the same (collective) benchmarks silently
    if (rank == 0)
      benchmark::RunSpecifiedBenchmarks();
    else
      benchmark::RunSpecifiedBenchmarks(&quiet);
    if (rank == 0 && gSecondsPerCall.count("specialised") && gSecondsPerCall.count("generic")) {
      const double sp = gSecondsPerCall["specialised"], g = gSecondsPerCall["generic"];
      std::printf("elastic residual on %d rank(s), %d cells: specialised %.3f ms, generic %.1f ms, ratio "
                  "specialised/generic %.4f (generic is %.0fx slower)\n",
                  size, static_cast<int>(model().mesh().globalCells()), 1e3 * sp, 1e3 * g, sp / g, g / sp);
    }
    if (rank == 0 && gSecondsPerCall.count("kernel dense") && gSecondsPerCall.count("kernel blocked"))
      std::printf("cell kernel alone: dense %.3f ms, blocked %.3f ms, ratio blocked/dense %.3f\n",
                  1e3 * gSecondsPerCall["kernel dense"], 1e3 * gSecondsPerCall["kernel blocked"],
                  gSecondsPerCall["kernel blocked"] / gSecondsPerCall["kernel dense"]);
    for (const char* kind : {"dense", "blocked"}) {
      const std::string one = std::string("kernel ") + kind, each = one + ", per-cell shape";
      if (rank == 0 && gSecondsPerCall.count(one) && gSecondsPerCall.count(each))
        std::printf("%s kernel, %zu cell shape(s): per-cell shape %.3f ms against one shape %.3f ms, ratio %.3f\n", kind,
                    model().mesh().shapes().size(), 1e3 * gSecondsPerCall[each], 1e3 * gSecondsPerCall[one],
                    gSecondsPerCall[each] / gSecondsPerCall[one]);
    }
    gModel.reset();
  });
}
