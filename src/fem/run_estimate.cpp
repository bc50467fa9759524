#include "gradfric/fem/run_estimate.hpp"

#include "gradfric/fem/stable_step.hpp"
#include "gradfric/fem/state_view.hpp"

#include <cmath>
#include <cstdio>

namespace gradfric::fem {

namespace {

// Measured (docs/fem.md, "Results and timings"): one rank steps a cell in ~80 ns (20 x 20 x 2:
// 0.062 ms per step; 100 x 100 x 5 on 2 ranks of an idle 16-core machine: 2.01 ms per step); and
// rank 0 peaks at ~47 MB + 2.2 KB per cell (maximum resident size, 50 x 50 x 10 and 100 x 100 x 10
// on one rank: 102 MB and 266 MB).
constexpr double kSecondsPerCellStep = 80e-9;
constexpr double kBaseMemory = 47e6, kMemoryPerCell = 2.2e3;

}  // namespace

RunEstimate estimateRun(const FemParameters& q, const Grading& grading, int ranks) {
  RunEstimate e;
  e.ranks = ranks;
  e.cells = static_cast<long long>(q.nx) * q.ny * q.nz;
  e.vertices = static_cast<long long>(q.nx + 1) * (q.ny + 1) * (q.nz + 1);
  e.unknowns = StateLayout::kBlock * e.vertices;
  e.rankZeroMemory = kBaseMemory + kMemoryPerCell * static_cast<double>(e.cells);
  const double dt = chooseTimeStep(q, grading);
  e.pressureSteps = q.staticPressureStep ? 0 : std::llround(std::ceil((q.rampTime + q.settleTime) / dt));
  e.slidingSteps = std::llround(std::ceil(q.slideTime / dt));
  e.wallSeconds = kSecondsPerCellStep * static_cast<double>(e.cells) *
                  static_cast<double>(e.pressureSteps + e.slidingSteps) / std::max(1, ranks);
  return e;
}

std::string RunEstimate::describe() const {
  char text[600];
  std::snprintf(text, sizeof text,
                "%lld cells, %lld vertices, %lld unknowns; memory ~%.0f MB on rank 0 (47 MB + 2.2 KB per cell, "
                "measured); %lld pressure steps + at most %lld sliding steps; ~%.0f s on %d rank(s) at 80 ns per "
                "cell-step per rank (an idle core; a run that stops at its observables takes less)",
                cells, vertices, unknowns, rankZeroMemory / 1e6, pressureSteps, slidingSteps, wallSeconds, ranks);
  return text;
}

}  // namespace gradfric::fem
