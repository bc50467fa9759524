// The rule both models use to turn a refinement ladder into an error bar
// (core/refinement_ladder.hpp), on sequences whose limit is known: mu(h) = mu0 + C h^p.
#include "gradfric/core/refinement_ladder.hpp"

#include "gradfric/campaign/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using gradfric::judgeLadder;
using gradfric::LadderOutcome;
using gradfric::LadderRung;
using gradfric::BoundedValue;
using gradfric::shareALimit;

constexpr double kLimit = 0.93;

// Rungs at h = 4, 2, 1 of mu0 + c h^p (coarse first).
void powerLadder(double c, double p, LadderRung (&rungs)[3]) {
  for (int k = 0; k < 3; ++k) rungs[k] = {kLimit + c * std::pow(2.0, p * (2 - k))};
}

TEST(RefinementLadder, SecondOrderIsExtrapolatedExactly) {
  LadderRung rungs[3];
  powerLadder(0.004, 2.0, rungs);
  for (int member = 0; member < 3; ++member) {
    const auto v = judgeLadder(rungs, member);
    ASSERT_EQ(v.outcome, LadderOutcome::Monotone);
    EXPECT_NEAR(v.order, 2.0, 1e-9);
    EXPECT_NEAR(v.extrapolated, kLimit, 1e-12);
    // Roache's GCI: 1.25 x the member's distance to the limit.
    EXPECT_NEAR(v.bound, 1.25 * std::fabs(rungs[member].value - kLimit) / kLimit, 1e-12);
  }
}

TEST(RefinementLadder, GciBoundsTheTrueErrorAtEveryOrderAboveOneHalf) {
  for (double p : {0.6, 1.0, 1.7, 2.0, 3.0, 4.0})
    for (double c : {0.01, -0.01}) {
      LadderRung rungs[3];
      powerLadder(c, p, rungs);
      for (int member = 0; member < 3; ++member) {
        const auto v = judgeLadder(rungs, member);
        ASSERT_EQ(v.outcome, LadderOutcome::Monotone) << "p " << p;
        EXPECT_NEAR(v.order, p, 1e-9);
        EXPECT_GE(v.bound, std::fabs(rungs[member].value / kLimit - 1)) << "p " << p << " member " << member;
      }
    }
}

TEST(RefinementLadder, OrderAtOrBelowOneHalfProvesNothing) {
  for (double p : {0.49, 0.3, 0.0, -0.5}) {
    LadderRung rungs[3];
    powerLadder(0.01, p, rungs);
    EXPECT_EQ(judgeLadder(rungs, 1).outcome, LadderOutcome::NotConverged) << "p " << p;
  }
}

TEST(RefinementLadder, AlternatingShrinkingBracketsTheLimit) {
  // mu0 + c (-1/2)^k: the differences alternate and halve.
  LadderRung rungs[3];
  for (int k = 0; k < 3; ++k) rungs[k] = {kLimit + 0.02 * std::pow(-0.5, k)};
  for (int member = 0; member < 3; ++member) {
    const auto v = judgeLadder(rungs, member);
    ASSERT_EQ(v.outcome, LadderOutcome::Oscillating);
    EXPECT_GE(v.bound, std::fabs(rungs[member].value / kLimit - 1));
  }
  // Alternating without shrinking by 1/sqrt(2): no bound (the FEM's friction +0.2 ladder).
  const LadderRung flat[3] = {{0.804064}, {0.805781}, {0.804198}};
  EXPECT_EQ(judgeLadder(flat, 2).outcome, LadderOutcome::NotConverged);
}

TEST(RefinementLadder, StatisticalDifferencesMustExceedTheirHalfWidths) {
  LadderRung rungs[3];
  powerLadder(0.004, 2.0, rungs);  // differences 0.048 and 0.012
  LadderRung noisy[3], precise[3];
  for (int k = 0; k < 3; ++k) {
    noisy[k] = {rungs[k].value, 0.01, 16};     // half-widths about 0.03: the second difference is noise
    precise[k] = {rungs[k].value, 1e-4, 64};  // half-widths about 3e-4
  }
  EXPECT_EQ(judgeLadder(noisy, 2).outcome, LadderOutcome::NoSignal);
  const auto deterministic = judgeLadder(rungs, 1), withError = judgeLadder(precise, 1);
  ASSERT_EQ(withError.outcome, LadderOutcome::Monotone);
  EXPECT_GT(withError.firstHalfWidth, 0.0);
  // The same means with a statistical error get a wider bar, by the half-width of mu(2n) - mu_ext.
  EXPECT_GT(withError.bound, deterministic.bound);
  EXPECT_LT(withError.bound - deterministic.bound, 0.01);
}

TEST(RefinementLadder, AValueIsBoundedThroughAFinerOneByTheTriangleInequality) {
  // mu(h) = 1 + 0.05 h^2 on h = 8 (a coarse run), and the ladder 4, 2, 1: the bound through mu(1)
  // must hold the true error of mu(8), 3.2 (relative 0.05 * 64 / 1).
  LadderRung finer[3];
  for (int k = 0; k < 3; ++k) finer[k] = {1.0 + 0.05 * std::pow(2.0, 2 * (2 - k))};
  const auto v = judgeLadder(finer, 2);
  ASSERT_EQ(v.outcome, LadderOutcome::Monotone);
  const LadderRung coarse{1.0 + 0.05 * 64};
  const double bound = boundThroughFinerValue(coarse, finer[2], v.bound);
  EXPECT_GE(bound, std::fabs(coarse.value - 1.0) / 1.0);
  EXPECT_GE(bound, (coarse.value - finer[2].value) / finer[2].value + v.bound);
  // Two ensemble means: the measured difference is widened by its 95 % half-width.
  const LadderRung a{0.90, 0.002, 10}, b{0.85, 0.001, 20};
  EXPECT_NEAR(boundThroughFinerValue(a, b, 0.01),
              (0.05 + gradfric::campaign::t95(9) * std::sqrt(0.002 * 0.002 + 0.001 * 0.001) + 0.01 * 0.85) / (0.99 * 0.85),
              1e-12);
}

TEST(RefinementLadder, BoundsShareALimitOnlyWhereTheirIntervalsOverlap) {
  // |v - L| <= b L holds L in [v / (1 + b), v / (1 - b)]: 1 +- 1 % holds [0.990, 1.010], 1.03 +- 1 %
  // holds [1.0198, 1.0404] (apart); at 2 % they are [0.980, 1.020] and [1.0098, 1.0510] (overlap).
  const BoundedValue apart[2] = {{1.0, 0.01}, {1.03, 0.01}}, overlap[2] = {{1.0, 0.02}, {1.03, 0.02}};
  EXPECT_FALSE(shareALimit(apart, 2));
  EXPECT_TRUE(shareALimit(overlap, 2));
  // The exact limit 1 of mu(h) = 1 + 0.05 h^2 lies in every bound that holds it: they share it.
  const BoundedValue exact[3] = {{1.2, 0.2}, {1.05, 0.05}, {1.0125, 0.0125}};
  EXPECT_TRUE(shareALimit(exact, 3));
  // 1.2 +- 20 % puts the limit at or above 1.0; 0.95 +- 4 % at or below 0.9896: refuted.
  const BoundedValue tight[2] = {{1.2, 0.2}, {0.95, 0.04}};
  EXPECT_FALSE(shareALimit(tight, 2));
  // A single bounded value shares a limit with itself; values of opposite signs share none.
  EXPECT_TRUE(shareALimit(apart, 1));
  const BoundedValue signs[2] = {{0.01, 0.5}, {-0.01, 0.5}};
  EXPECT_FALSE(shareALimit(signs, 2));
}

}  // namespace
