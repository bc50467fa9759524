#pragma once
// The process zone of a slip-weakening interface, measured from a run (as SeisSol's cohesive-zone
// estimate, (t_weakened - t_start) times the front speed): at each interface node, the length
// behind the slip front over which the strength falls from mu_s to mu_k,
//   Lambda = (t_end - t_start) / |grad t_start|,
// t_start the time its strength first fell below mu_k + 0.9 (mu_s - mu_k), t_end below
// mu_k + 0.1 (mu_s - mu_k), |grad t_start| the front's slowness from the neighbouring nodes of the
// tensor-product grid. Day et al. (2005) and Dalguer & Day (2007) ask for a median of at least
// 4-5 elements across it for converged ruptures. Pure arithmetic, no PETSc.
#include <vector>

namespace gradfric {

struct WeakeningTimes {  // one entry per interface node; a time < 0: never reached
  std::vector<double> x, y, start, end;
};

struct ProcessZone {
  int nodes = 0;                  // nodes with a measured zone
  double median = 0, low = 0;     // median and 10th percentile of Lambda [m]
  double medianElements = 0, lowElements = 0;  // the same in local element sizes along the front
};

// Over the nodes whose weakening started by latestStart (the peak: the zone that decides mu_s).
ProcessZone measureProcessZone(const WeakeningTimes& times, double latestStart);

}  // namespace gradfric
