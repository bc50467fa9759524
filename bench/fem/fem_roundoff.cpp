// Round-off growth of the FEM's friction history (docs/studies/fem-cost.md): the same scene
// run with the cells taken in a shuffled order (pattern k = 1 .. runs-1; run 0 in the mesh's
// order), with the dense and the blocked elastic kernel, and optionally again at dt/2. Every node
// then sums its cells' forces in another order, as on another number of ranks: the forces change
// by round-off only, and the spread of mu(t), mu_s and mu_k over these runs is the growth of
// round-off through the chaotic post-peak history: the floor under which two results that differ
// only in the order of their sums (dense vs blocked, 1 vs 2 ranks) cannot be told apart.
// The tolerances of the tests that compare such results (fem_parallel, fem_hard_numerics) are set
// from what this prints.
//   bench/fem/bench_fem_roundoff -fem_nx 12 -fem_ny 10 -fem_nz 2 -grading_profile linear
//       -grading_property both -grading_delta 0.2 -roundoff_runs 6
//   (add -roundoff_half_dt to also run each at dt/2 and print mu_k(dt)/mu_k(dt/2) - 1)
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"

#include <petscsys.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

static const char help[] = "bench_fem_roundoff: spread of mu(t), mu_s, mu_k under one-ulp changes, dense and blocked kernel\n";

namespace {

struct Run {
  bool blocked = false;
  int ulps = 0;
  bool halfDt = false;
  gradfric::fem::FemRunResult result;
};

double worstRelativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return INFINITY;
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::fabs(a[i] - b[i]) / std::max(1e-300, std::fabs(a[i])));
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace gradfric;
  using namespace gradfric::fem;
  return runDriver(argc, argv, help, [](MPI_Comm comm) {
    RunParameters record;
    OptionReader own(comm, "roundoff_", "Round-off study", &record);
    const int runs = static_cast<int>(own.integer("runs", 4, 1, 64, "1", "runs per kernel (run k > 0: cells in shuffled order k)"));
    const bool halfDt = own.flag("half_dt", false, "also run each at dt/2 (mu_s, mu_k ratios dt vs dt/2)");
    const std::optional<FemScene> scene = readCheckedFemScene(comm, &record, {"roundoff_"});
    if (!scene) return;
    FemParameters base = scene->params;
    base.verbose = false;
    std::vector<Run> all;
    for (bool blocked : {false, true})
      for (int k = 0; k < runs; ++k)
        for (int h = 0; h < (halfDt ? 2 : 1); ++h) {
          FemParameters q = base;
          q.blockedKernel = blocked;
          if (h == 1) q.dt = 0.5 * q.dt.value_or(q.dtSafety * stableTimeStep(q, scene->grading));
          PlateModel model(comm, q, scene->grading);
          model.elastic().shuffleCellOrder(static_cast<unsigned>(k));
          Run r{blocked, k, h == 1, runPlateExperiment(model)};
          const FrictionSummary& f = r.result.friction;
          PetscPrintf(comm, "  %-7s pattern %d%s: %zu samples, mu_s %.12f, mu_k %.12f\n", blocked ? "blocked" : "dense", k,
                      h ? " dt/2" : "     ", r.result.mu.size(), f.muStatic, f.muKinetic);
          all.push_back(std::move(r));
        }
    // Spreads: over all pairs of full-dt runs (within a kernel, and dense against blocked).
    auto spread = [&](int kernels) {  // 0: dense pairs, 1: blocked pairs, 2: dense vs blocked
      double mu = 0, muS = 0, muK = 0;
      for (const Run& a : all)
        for (const Run& b : all) {
          if (a.halfDt || b.halfDt || &a >= &b) continue;
          const bool same = a.blocked == b.blocked;
          if ((kernels == 2) == same || (kernels < 2 && a.blocked != (kernels == 1))) continue;
          mu = std::max(mu, worstRelativeDifference(a.result.mu, b.result.mu));
          muS = std::max(muS, std::fabs(a.result.friction.muStatic / b.result.friction.muStatic - 1));
          muK = std::max(muK, std::fabs(a.result.friction.muKinetic / b.result.friction.muKinetic - 1));
        }
      return std::array<double, 3>{mu, muS, muK};
    };
    const char* names[] = {"dense vs dense", "blocked vs blocked", "dense vs blocked"};
    PetscPrintf(comm, "largest relative differences over pairs of runs (round-off alone):\n");
    for (int s = 0; s < 3; ++s) {
      const auto d = spread(s);
      PetscPrintf(comm, "  %-20s mu(t) %.3e, mu_s %.3e, mu_k %.3e\n", names[s], d[0], d[1], d[2]);
    }
    if (halfDt) {
      PetscPrintf(comm, "dt vs dt/2 per run (mu_s(dt)/mu_s(dt/2) - 1, the same for mu_k):\n");
      for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
        const FrictionSummary &a = all[i].result.friction, &b = all[i + 1].result.friction;
        PetscPrintf(comm, "  %-7s pattern %d: mu_s %+.3e, mu_k %+.3e\n", all[i].blocked ? "blocked" : "dense", all[i].ulps,
                    a.muStatic / b.muStatic - 1, a.muKinetic / b.muKinetic - 1);
      }
    }
  });
}
