// Precision on demand (include/gradfric/campaign/precision_target.hpp).
#include "gradfric/campaign/precision_target.hpp"

#include "gradfric/physics/observables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gradfric::campaign {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TargetKind targetKindOf(const std::string& name) {
  if (name == "absolute") return TargetKind::Absolute;
  if (name == "relative") return TargetKind::Relative;
  if (name == "variation") return TargetKind::Variation;
  throw std::invalid_argument("unknown target kind " + name);
}

std::string toString(TargetKind kind) {
  switch (kind) {
    case TargetKind::Relative: return "relative";
    case TargetKind::Variation: return "variation";
    default: return "absolute";
  }
}

double achievedHalfWidth(const PrecisionTarget& target, const std::vector<PointStatistics>& statistics,
                         const std::vector<int>& reference, int p) {
  // The target is about mu_s (-ensemble_target_type).
  const ObservableStatistics& s = statistics[p].observables.at(statisticsIndex("mu_s"));
  const int n = s.summary.count;
  switch (target.kind) {
    case TargetKind::Absolute: return n >= 2 ? s.summary.ciHalfWidth() : kNaN;
    case TargetKind::Relative: return n >= 2 ? s.summary.ciHalfWidth() / std::fabs(s.summary.mean) : kNaN;
    case TargetKind::Variation: {
      const int q = reference[p];
      if (q < 0) return kNaN;
      if (q == p) return 0.0;
      // The printed and stored 95 % half-width itself (statistics.hpp: the pairs, or with
      // independent streams the smaller sample, set the degrees of freedom).
      return s.relative.halfWidth;
    }
  }
  return kNaN;
}

std::vector<int> planNextBatch(const PrecisionTarget& target, const std::vector<int>& counts,
                               const std::vector<PointStatistics>& statistics, const std::vector<int>& reference) {
  const int points = static_cast<int>(counts.size());
  std::vector<int> next(counts);
  for (int p = 0; p < points; ++p) {
    const int n = counts[p];
    if (n >= target.cap) continue;
    const double h = achievedHalfWidth(target, statistics, reference, p);
    if (h <= target.halfWidth) continue;  // met (NaN compares false: not met)
    double want = 2.0 * n;                // no estimate yet: double
    if (std::isfinite(h)) want = std::ceil(1.1 * n * (h / target.halfWidth) * (h / target.halfWidth));
    const double most = std::min(static_cast<double>(target.cap), 3.0 * n);
    next[p] = static_cast<int>(std::clamp(want, n + 1.0, std::max(most, n + 1.0)));
  }
  if (target.kind == TargetKind::Variation)
    for (int p = 0; p < points; ++p) {
      const int q = reference[p];
      if (q >= 0 && q != p) next[q] = std::min(target.cap, std::max(next[q], next[p]));
    }
  return next;
}

std::vector<PointStatistics> statisticsOfCounts(const std::vector<int>& counts, int realisations,
                                                const std::vector<int>& reference,
                                                const std::vector<std::vector<double>>& tables,
                                                const std::vector<signed char>& peakConfirmed,
                                                const std::vector<unsigned char>& done, bool paired) {
  std::vector<unsigned char> within(done.size(), 0);
  const size_t R = static_cast<size_t>(realisations);
  for (size_t p = 0; p < counts.size(); ++p)
    for (size_t r = 0; r < static_cast<size_t>(counts[p]) && r < R; ++r) within[p * R + r] = done[p * R + r];
  return pointStatistics(realisations, reference, tables, peakConfirmed, within, paired);
}

}  // namespace gradfric::campaign
