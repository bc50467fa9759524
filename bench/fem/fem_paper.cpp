// The paper-mesh benchmark (docs/studies/fem-cost.md): one FEM run at the defaults (100 x 100 x 5,
// pressure step, sliding through the kinetic window) with the ordinary -plate_/-grading_/-fem_/
// -friction_ options, printing the steps and wall time of step 1 (pressure) and step 2 (sliding),
// the ms per step, the results (to check that a faster build gives the same numbers), the load
// average before and after, and the PETSc log events of the run (time on the slowest rank).
//   nice -n 10 mpiexec -n 2 bench/fem/bench_fem_paper
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"

#include <petscsys.h>

#include <cmath>
#include <ctime>
#include <optional>
#include <fstream>
#include <string>

static const char help[] = "bench_fem_paper: wall time, steps and PETSc event breakdown of one FEM run\n";

namespace {

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0;
  if (!(in >> one >> five)) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f (1 min), %.2f (5 min)", one, five);
  return text;
}

double cpuSeconds() {  // this process, all threads
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

struct EventTime {
  double seconds = 0;  // slowest rank
  long count = 0;
};

EventTime eventTime(MPI_Comm comm, const char* name) {
  PetscLogEvent id = -1;
  GF_CALL(PetscLogEventGetId(name, &id));
  PetscEventPerfInfo info{};
  if (id >= 0) GF_CALL(PetscLogEventGetPerfInfo(PETSC_DETERMINE, id, &info));
  double local = info.time, slowest = 0;
  GF_CALL_MPI(MPI_Allreduce(&local, &slowest, 1, MPI_DOUBLE, MPI_MAX, comm));
  return {slowest, static_cast<long>(info.count)};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace gradfric;
  using namespace gradfric::fem;
  return runDriver(argc, argv, help, [](MPI_Comm comm) {
    RunParameters record;
    const std::optional<FemScene> scene = readCheckedFemScene(comm, &record);  // the driver's options and checks
    if (!scene) return;  // -help
    const Grading& grading = scene->grading;
    FemParameters params = scene->params;
    params.verbose = false;
    int ranks = 1;
    MPI_Comm_size(comm, &ranks);
    GF_CALL(PetscLogDefaultBegin());
    const std::string loadBefore = loadAverage();
    const double setup0 = MPI_Wtime();
    PlateModel model(comm, params, grading);
    const double setup = MPI_Wtime() - setup0;
    const double cpu0 = cpuSeconds();
    const FemRunResult r = runPlateExperiment(model);
    const double cpuLocal = cpuSeconds() - cpu0;
    double cpu = 0;  // the busiest rank's CPU time: with a loaded machine, the load-free measure of the work
    GF_CALL_MPI(MPI_Allreduce(&cpuLocal, &cpu, 1, MPI_DOUBLE, MPI_MAX, comm));
    const std::string loadAfter = loadAverage();
    const long slideSteps = static_cast<long>(r.mu.size());
    const long pressureSteps = r.steps - slideSteps;
    const double wall = r.wallPressure + r.wallSliding;
    const std::string staticNote =
        r.staticPressureStep ? " (" + std::to_string(r.pressureIterations) + " CG iterations)" : "";
    PetscPrintf(comm,
                "bench_fem_paper: mesh %dx%dx%d, element %s, kernel %s, %d ranks, dt %.4e s (stable %.4e s)\n"
                "  load average before %s, after %s\n"
                "  set-up %.2f s\n"
                "  step 1 (pressure, %s): %ld steps%s, %.2f s wall, %.3f ms/step\n"
                "  step 2 (sliding):  %ld steps, %.2f s wall, %.3f ms/step\n"
                "  total: %ld steps, %.2f s wall (%.3f ms/step); CPU of the busiest rank %.2f s (%.3f ms/step)\n"
                "  results: mu_s %.6f (peak at %.6e s, confirmed %d), mu_k %.6f, settled normal force %.6f p L^2\n",
                params.nx, params.ny, params.nz, elementTypeName(params.element), params.blockedKernel ? "blocked" : "dense", ranks, r.dt, r.stableDt,
                loadBefore.c_str(), loadAfter.c_str(), setup, r.staticPressureStep ? "static" : "dynamic", pressureSteps,
                staticNote.c_str(), r.wallPressure,
                1e3 * r.wallPressure / std::max(1L, pressureSteps), slideSteps, r.wallSliding,
                1e3 * r.wallSliding / std::max(1L, slideSteps), r.steps, wall, 1e3 * wall / std::max(1L, r.steps), cpu, 1e3 * cpu / std::max(1L, r.steps),
                r.friction.muStatic, r.friction.peakTime, r.friction.peakConfirmed ? 1 : 0, r.friction.muKinetic,
                r.settledNormalForce);
    // What each event is (times on the slowest rank, inclusive of nested events).
    const struct {
      const char* name;
      const char* what;
    } events[] = {
        {"TSStep", "whole Verlet step (kicks, drift, right-hand side)"},
        {"GfFemRHS", "right-hand side (all of it)"},
        {"GfFemElastic", "  elastic kernel (cells)"},
        {"GfFemContact", "  contact (bottom nodes)"},
        {"SFBcastBegin", "  ghost exchange global -> local: start"},
        {"SFBcastEnd", "  ghost exchange global -> local: finish (waits)"},
        {"SFReduceBegin", "  ghost sum local -> global: start"},
        {"SFReduceEnd", "  ghost sum local -> global: finish (waits, adds)"},
        {"GfFemPostStep", "post-step: contact commit, totals over ranks, mu(t)"},
        {"GfFemMonitor", "blow-up/energy monitor"},
        {"GfFemOutput", "snapshot output"},
    };
    const EventTime step = eventTime(comm, "TSStep"), rhs = eventTime(comm, "GfFemRHS");
    PetscPrintf(comm, "  PETSc log events (slowest rank): %-56s %9s %8s %9s %6s\n", "", "time [s]", "count",
                "ms/step", "% wall");
    for (const auto& e : events) {
      const EventTime t = eventTime(comm, e.name);
      PetscPrintf(comm, "    %-16s %-70s %9.3f %8ld %9.4f %6.1f\n", e.name, e.what, t.seconds, t.count,
                  1e3 * t.seconds / std::max(1L, r.steps), 100 * t.seconds / wall);
    }
    const double verlet = step.seconds - rhs.seconds;
    PetscPrintf(comm, "    %-16s %-70s %9.3f %8s %9.4f %6.1f\n", "(derived)",
                "Verlet kicks and drift (TSStep - GfFemRHS)", verlet, "", 1e3 * verlet / std::max(1L, r.steps),
                100 * verlet / wall);
  });
}
