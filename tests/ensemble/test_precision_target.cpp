// The batch plan of a precision target: met points stop, unmet points grow towards the count their
// standard error predicts (at least +1, at most x3, never past the cap), the reference of a
// variation target grows with its points, and the half-widths are the 95 % CI's.
#include "gradfric/campaign/precision_target.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric::campaign;

namespace {

// A point whose n values have standard deviation sd about mean (statistics as pointStatistics makes them).
PointStatistics pointOf(int n, double mean, double sd) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(mean + (i % 2 ? sd : -sd) * std::sqrt((n - 1.0) / n));
  PointStatistics s;
  s.observables = {{summarise(v), {}}, {summarise({}), {}}};  // mu_s, mu_k (physics/observables.hpp)
  s.finished = n;
  return s;
}

PrecisionTarget absoluteTarget(double h, int cap = 100) {
  PrecisionTarget t;
  t.kind = TargetKind::Absolute;
  t.halfWidth = h;
  t.first = 4;
  t.cap = cap;
  return t;
}

}  // namespace

TEST(PrecisionTarget, HalfWidthIsTheStudentInterval) {
  const PointStatistics s = pointOf(10, 0.9, 0.01);
  const std::vector<PointStatistics> stats{s};
  const double expected = studentTQuantile(0.975, 9) * s.observables[0].summary.stdDev / std::sqrt(10.0);
  EXPECT_NEAR(achievedHalfWidth(absoluteTarget(1), stats, {0}, 0), expected, 1e-15);
  PrecisionTarget relative = absoluteTarget(1);
  relative.kind = TargetKind::Relative;
  EXPECT_NEAR(achievedHalfWidth(relative, stats, {0}, 0), expected / 0.9, 1e-15);
  EXPECT_TRUE(std::isnan(achievedHalfWidth(absoluteTarget(1), {pointOf(1, 0.9, 0)}, {0}, 0)));
}

TEST(PrecisionTarget, MetPointsStopUnmetGrowWhereTheVarianceIs) {
  // Same count, sd 0.002 and 0.02: the quiet point meets 0.004, the noisy one needs about 100x more.
  const std::vector<PointStatistics> stats{pointOf(10, 0.9, 0.002), pointOf(10, 0.9, 0.02)};
  const std::vector<int> next = planNextBatch(absoluteTarget(0.004), {10, 10}, stats, {0, 0});
  EXPECT_EQ(next[0], 10);
  EXPECT_EQ(next[1], 30);  // at most threefold per batch
  // Nearly met: at least one more.
  const std::vector<PointStatistics> close{pointOf(10, 0.9, 0.00562)};
  const double h = achievedHalfWidth(absoluteTarget(1), close, {0}, 0);
  ASSERT_GT(h, 0.004);
  const int grown = planNextBatch(absoluteTarget(0.004), {10}, close, {0})[0];
  EXPECT_EQ(grown, static_cast<int>(std::ceil(1.1 * 10 * (h / 0.004) * (h / 0.004))));
  EXPECT_GE(grown, 11);
  // The cap bounds it, and a point at the cap is left alone.
  EXPECT_EQ(planNextBatch(absoluteTarget(0.004, 12), {10, 10}, stats, {0, 0})[1], 12);
  EXPECT_EQ(planNextBatch(absoluteTarget(0.004, 10), {10, 10}, stats, {0, 0}), (std::vector<int>{10, 10}));
}

TEST(PrecisionTarget, NoEstimateDoublesAndVariationGrowsTheReference) {
  const std::vector<PointStatistics> one{pointOf(1, 0.9, 0.0)};
  EXPECT_EQ(planNextBatch(absoluteTarget(0.004), {1}, one, {0})[0], 2);
  PrecisionTarget variation = absoluteTarget(0.001);
  variation.kind = TargetKind::Variation;
  std::vector<PointStatistics> stats{pointOf(8, 0.9, 0.001), pointOf(8, 0.7, 0.01)};
  stats[0].observables[0].relative = relativeVariation(stats[0].observables[0].summary, stats[0].observables[0].summary, true);
  stats[1].observables[0].relative = relativeVariation(stats[1].observables[0].summary, stats[0].observables[0].summary, false);
  EXPECT_EQ(achievedHalfWidth(variation, stats, {0, 0}, 0), 0.0);  // the reference itself
  // The printed and stored half-width: the propagated error times t of the smaller sample's 7 dof.
  const double error = stats[1].observables[0].relative.error;
  ASSERT_GT(error, 0.0);
  EXPECT_NEAR(achievedHalfWidth(variation, stats, {0, 0}, 1), studentTQuantile(0.975, 7) * error, 1e-15);
  EXPECT_EQ(achievedHalfWidth(variation, stats, {0, 0}, 1), stats[1].observables[0].relative.halfWidth);
  const std::vector<int> next = planNextBatch(variation, {8, 8}, stats, {0, 0});
  EXPECT_EQ(next[1], 24);
  EXPECT_EQ(next[0], 24);  // every realisation of point 1 keeps its pair
}

TEST(PrecisionTarget, StatisticsSeeOnlyThePlannedRealisations) {
  // 2 points x 4 realisations, all done; counts 2 and 3: the statistics use those only.
  const std::vector<double> mu{1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<signed char> confirmed(8, 1);
  const std::vector<unsigned char> done(8, 1);
  const auto s = statisticsOfCounts({2, 3}, 4, {0, 0}, {mu, mu}, confirmed, done, false);
  EXPECT_EQ(s[0].finished, 2);
  EXPECT_DOUBLE_EQ(s[0].observables[0].summary.mean, 1.5);
  EXPECT_EQ(s[1].finished, 3);
  EXPECT_DOUBLE_EQ(s[1].observables[0].summary.mean, 6.0);
}
