#pragma once
// Precision on demand (-ensemble_target): the half-width of a 95 % confidence interval each sweep
// point must reach, and the batch plan that gets there. Pure functions, no MPI, no I/O: a run
// (task_runner.cpp) or a design loop calls planNextBatch with the statistics of its completed
// batches and runs the realisations it asks for, until it returns the same counts.
//
// Decisions depend only on the values of completed realisations, taken in point order, never on
// timing or on the number of ranks: the same scene and seed give the same plan anywhere, and a
// resumed run replays the plan from its file.
#include "gradfric/campaign/statistics.hpp"

#include <string>
#include <vector>

namespace gradfric::campaign {

enum class TargetKind {
  Absolute,   // half-width of the 95 % CI of mean mu_s
  Relative,   // the same divided by |mean mu_s|
  Variation,  // half-width of the 95 % CI of (mu_s - mu_s,0) / mu_s,0 against the reference point
};

struct PrecisionTarget {
  TargetKind kind = TargetKind::Absolute;
  double halfWidth = 0.0;  // 0: no target (a fixed count of realisations)
  int first = 8;           // realisations per point of the first batch (>= 2)
  int cap = 200;           // at most this many realisations per point
  bool active() const { return halfWidth > 0.0; }
};

TargetKind targetKindOf(const std::string& name);  // absolute, relative, variation
std::string toString(TargetKind kind);

// The achieved half-width of the quantity the target is about at point p (NaN while it cannot be
// estimated: fewer than 2 values or pairs). A reference point (reference[p] == p) of a variation
// target reports 0: its precision enters through the points compared with it.
double achievedHalfWidth(const PrecisionTarget& target, const std::vector<PointStatistics>& statistics,
                         const std::vector<int>& reference, int p);

// Counts per point for the next batch, given the counts of the completed batches and their
// statistics (computed over exactly those realisations). Returns `counts` itself when every point
// meets the target or has reached the cap. An unmet point grows towards the count its current
// standard error predicts (n (h / target)^2, 10 % margin), at least by one and at most threefold
// per batch (early variance estimates are noisy); under a variation target the reference point
// grows with the points compared with it, so that every realisation of a point has its pair.
std::vector<int> planNextBatch(const PrecisionTarget& target, const std::vector<int>& counts,
                               const std::vector<PointStatistics>& statistics, const std::vector<int>& reference);

// Statistics of every point over realisations r < counts[p] that are done (P x R tables as for
// pointStatistics): what the plan sees of a file that may hold more.
std::vector<PointStatistics> statisticsOfCounts(const std::vector<int>& counts, int realisations,
                                                const std::vector<int>& reference,
                                                const std::vector<std::vector<double>>& tables,
                                                const std::vector<signed char>& peakConfirmed,
                                                const std::vector<unsigned char>& done, bool paired);

}  // namespace gradfric::campaign
