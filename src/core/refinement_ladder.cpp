// The rule of include/gradfric/core/refinement_ladder.hpp.
#include "gradfric/core/refinement_ladder.hpp"

#include "gradfric/campaign/statistics.hpp"  // t95

#include <algorithm>
#include <cmath>

namespace gradfric {

namespace {

// 95 % half-width of sum_i c_i value_i over independent rungs, Student's t of the smallest sample
// used; 0 when every rung used is deterministic.
double halfWidthOf(const LadderRung (&m)[3], const double (&c)[3]) {
  double variance = 0;
  int smallest = 0;
  for (int i = 0; i < 3; ++i) {
    if (c[i] == 0.0 || m[i].stdError == 0.0) continue;
    variance += c[i] * c[i] * m[i].stdError * m[i].stdError;
    smallest = smallest == 0 ? m[i].realisations : std::min(smallest, m[i].realisations);
  }
  return variance == 0.0 ? 0.0 : campaign::t95(smallest - 1) * std::sqrt(variance);
}

}  // namespace

LadderVerdict judgeLadder(const LadderRung (&m)[3], int member) {
  LadderVerdict v;
  const double fine = m[2].value, run = m[member].value;
  v.first = m[1].value - m[0].value;
  v.second = fine - m[1].value;
  const double firstOf[3] = {-1, 1, 0}, secondOf[3] = {0, -1, 1};
  v.firstHalfWidth = halfWidthOf(m, firstOf);
  v.secondHalfWidth = halfWidthOf(m, secondOf);
  v.order = std::log(std::fabs(v.first / v.second)) / std::log(2.0);
  const bool statistical = m[0].stdError > 0 || m[1].stdError > 0 || m[2].stdError > 0;
  if (statistical && (!(std::fabs(v.first) > v.firstHalfWidth) || !(std::fabs(v.second) > v.secondHalfWidth))) {
    v.outcome = LadderOutcome::NoSignal;
    return v;
  }
  if (!(std::fabs(v.second) + v.secondHalfWidth < (std::fabs(v.first) - v.firstHalfWidth) / std::sqrt(2.0))) {
    v.outcome = LadderOutcome::NotConverged;
    return v;
  }
  if (v.first * v.second <= 0) {  // alternating (or a last step of zero): the limit lies between the last two
    const int far = std::fabs(run - m[1].value) > std::fabs(run - fine) ? 1 : 2;
    double c[3] = {0, 0, 0};
    c[member] += 1;
    c[far] -= 1;
    v.outcome = LadderOutcome::Oscillating;
    v.bound = 1.25 * (std::fabs(run - m[far].value) + halfWidthOf(m, c)) / std::fabs(fine);
    return v;
  }
  const double ratio = 1.0 / (std::pow(2.0, std::min(v.order, 2.0)) - 1.0);  // mu_ext = fine + ratio (fine - medium)
  v.extrapolated = fine + ratio * v.second;
  double c[3] = {0, ratio, -1 - ratio};
  c[member] += 1;
  v.outcome = LadderOutcome::Monotone;
  v.bound = 1.25 * (std::fabs(run - v.extrapolated) + halfWidthOf(m, c)) / std::fabs(v.extrapolated);
  return v;
}

double boundThroughFinerValue(const LadderRung& value, const LadderRung& finer, double finerBound) {
  const LadderRung pair[3] = {value, finer, {}};
  const double difference[3] = {1, -1, 0};
  // |mu - mu_lim| <= |mu - f| + h + b |f|, relative to |mu_lim| >= (1 - b) |f| (b: f's relative bound).
  const double f = std::fabs(finer.value);
  return (std::fabs(value.value - finer.value) + halfWidthOf(pair, difference) + finerBound * f) / ((1.0 - finerBound) * f);
}

bool shareALimit(const BoundedValue* values, int count) {
  double low = 0, high = INFINITY;  // of |L|; the values share one sign or none is bounded
  for (int i = 0; i < count; ++i) {
    const double v = std::fabs(values[i].value), b = values[i].bound;
    if (i > 0 && values[i].value * values[0].value <= 0) return false;
    low = std::max(low, v / (1.0 + b));
    if (b < 1.0) high = std::min(high, v / (1.0 - b));
  }
  return low <= high;
}

}  // namespace gradfric
