// The one verification procedure (include/gradfric/core/verification.hpp) on synthetic ladders of
// known limit: each case of the procedure, and the coverage of its bar by Monte Carlo.
#include "gradfric/core/verification.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace {

using namespace gradfric::verification;

// phi(h) = limit + a h^p + b h^q on the cell sizes h (deterministic members).
std::vector<Member> ladderOf(const std::vector<double>& h, double limit, double a, double p, double b = 0,
                             double q = 2) {
  std::vector<Member> m;
  for (double x : h) m.push_back({x, limit + a * std::pow(x, p) + b * std::pow(x, q)});
  return m;
}

bool contains(const Verdict& v, double limit) { return std::fabs(v.value - limit) <= v.uncertainty; }

std::string describe(const Verdict& v) {
  return std::string(toString(v.convergence)) + ", " + toString(v.fit) + ", U " + std::to_string(v.uncertainty);
}

TEST(Verification, AMonotoneLadderInTheAsymptoticRangeIsRichardsonWithSafetyFactor125) {
  // Three members at ratio 2, p = 1.5: the fit is exact, phi_0 the limit, U = 1.25 |phi - phi_0|.
  const std::vector<Member> m = ladderOf({4, 2, 1}, 0.9, 0.01, 1.5);
  for (int member = 0; member < 3; ++member) {
    const Verdict v = judge(m, member);
    EXPECT_EQ(v.convergence, Convergence::Monotone);
    EXPECT_EQ(v.fit, ErrorFit::ObservedOrder);
    EXPECT_NEAR(v.order, 1.5, 1e-6);
    EXPECT_NEAR(v.extrapolated, 0.9, 1e-9);
    EXPECT_DOUBLE_EQ(v.safetyFactor, 1.25);
    EXPECT_NEAR(v.uncertainty, 1.25 * std::fabs(m[member].value - 0.9), 1e-9);
  }
}

TEST(Verification, AnyRefinementRatiosAndMoreMembersAreFittedByLeastSquares) {
  // Five members at uneven ratios on phi = 1 + 0.3 h^1.2 (h in mm): p and the limit recovered.
  const Verdict v = judge(ladderOf({0.1, 0.07, 0.05, 0.03, 0.02}, 1.0, 0.3, 1.2), 4);
  EXPECT_EQ(v.convergence, Convergence::Monotone);
  EXPECT_NEAR(v.order, 1.2, 1e-4);
  EXPECT_NEAR(v.extrapolated, 1.0, 1e-7);
  EXPECT_NEAR(v.fitStdDev, 0.0, 1e-9);
}

TEST(Verification, AnOrderOutsideTheRangeUsesTheFixedOrderFitsWithSafetyFactor3) {
  // p = 0.3 < 0.5: Eca and Hoekstra's fixed-order fits would give 1.7 % while the error is 2.4 %,
  // so such a ladder gets no bar.
  const Verdict slow = judge(ladderOf({8, 4, 2, 1}, 0.8, 0.02, 0.3), 3);
  EXPECT_EQ(slow.convergence, Convergence::SlowConvergence);
  EXPECT_FALSE(slow.bounded());
  // p = 3 >= 2: the observed order is not trusted, the fixed-order fits with Fs = 3 bound it.
  const Verdict fast = judge(ladderOf({4, 2, 1}, 0.8, 0.001, 3), 2);
  EXPECT_DOUBLE_EQ(fast.safetyFactor, 3.0);
  EXPECT_TRUE(contains(fast, 0.8)) << describe(fast);
}

TEST(Verification, ACrossingLadderGetsTheDataRangeBoundNeverABracket) {
  // phi = 1 + h - 1.2 h^2 on h = 1, 1/2, 1/4: 0.8, 1.2, 1.175. The differences alternate (+0.4,
  // -0.025) and shrink: the rule of before took the limit to lie between the last two values
  // (1.175 to 1.2, a 2.7 % bracket of the finest) while the limit is 1, 15 % below it.
  const std::vector<Member> m = {{1, 0.8}, {0.5, 1.2}, {0.25, 1.175}};
  const Verdict v = judge(m, 2);
  EXPECT_EQ(v.convergence, Convergence::Oscillatory);
  EXPECT_DOUBLE_EQ(v.safetyFactor, 3.0);
  EXPECT_GE(v.uncertainty, 3 * (1.2 - 0.8)) << "at least three times the data range";
  EXPECT_TRUE(contains(v, 1.0)) << describe(v);
  const double bracketOfBefore = 1.25 * std::fabs(1.175 - 1.2);
  EXPECT_FALSE(std::fabs(1.175 - 1.0) <= bracketOfBefore) << "the old bracket excluded the limit";
}

TEST(Verification, ADivergentLadderHasNoBar) {
  EXPECT_EQ(judge(ladderOf({4, 2, 1}, 1.0, 0.01, -1), 2).convergence, Convergence::MonotoneDivergence);
  const Verdict growing = judge({{4, 1.0}, {2, 1.01}, {1, 0.98}}, 2);  // alternating, differences growing
  EXPECT_EQ(growing.convergence, Convergence::OscillatoryDivergence);
  EXPECT_FALSE(growing.bounded());
  EXPECT_FALSE(judge({{2, 1.0}, {1, 0.99}}, 1).bounded()) << "two members prove nothing";
  EXPECT_EQ(judge({{2, 1.0}, {1, 0.99}}, 1).convergence, Convergence::TooFewMembers);
}

TEST(Verification, DifferencesWithinTheNoiseGiveTheDataRangeBoundWithTheHalfWidth) {
  // Ensemble means that differ by less than their noise: no sign is known.
  const std::vector<Member> m = {{4, 0.9001, 2e-4, 50}, {2, 0.8999, 2e-4, 50}, {1, 0.9000, 2e-4, 50}};
  const Verdict v = judge(m, 2);
  EXPECT_EQ(v.convergence, Convergence::NoSignal);
  EXPECT_TRUE(v.bounded());
  EXPECT_GT(v.halfWidth, 0.0);
  EXPECT_NEAR(v.uncertainty, 3 * (0.9001 - 0.8999) + v.halfWidth, 1e-12);
}

TEST(Verification, AZeroDifferenceHasNoSignEither) {
  const Verdict v = judge({{4, 1.02}, {2, 1.0}, {1, 1.0}}, 2);
  EXPECT_EQ(v.convergence, Convergence::NoSignal);
  EXPECT_NEAR(v.uncertainty, 3 * 0.02, 1e-12);
}

TEST(Verification, TheHalfWidthOfTheMeansIsAddedToAFittedBar) {
  const std::vector<Member> exact = ladderOf({4, 2, 1}, 0.9, 0.02, 1.5);
  std::vector<Member> noisy = exact;
  for (Member& x : noisy) x.stdError = 1e-4, x.samples = 100;
  const Verdict a = judge(exact, 2), b = judge(noisy, 2);
  EXPECT_GT(b.halfWidth, 0.0);
  EXPECT_NEAR(b.uncertainty, a.uncertainty + 1.25 * b.halfWidth, 1e-12) << "under the safety factor";
}

// Coverage: on noisy ladders of known limit the bar of the finest member holds the limit in at least
// 95 % of the draws (Monte Carlo, fixed seed), for orders in and out of the range.
TEST(Verification, TheBarCoversTheLimitInAtLeast95PercentOfNoisyLadders) {
  std::mt19937_64 random(20141);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const double p : {0.7, 1.4, 2.5}) {
    int covered = 0, bounded = 0;
    const int draws = 2000;
    for (int k = 0; k < draws; ++k) {
      std::vector<Member> m;
      for (double h : {8.0, 4.0, 2.0, 1.0}) {
        const double stdError = 1e-3;
        m.push_back({h, 0.9 + 0.01 * std::pow(h, p) + stdError * normal(random), stdError, 30});
      }
      const Verdict v = judge(m, 3);
      if (!v.bounded()) continue;
      ++bounded;
      covered += contains(v, 0.9);
    }
    std::printf("coverage at p %.1f: %d of %d bounded ladders (%d drawn)\n", p, covered, bounded, draws);
    EXPECT_GT(bounded, draws / 2) << "p " << p;
    EXPECT_GE(covered, 0.95 * bounded) << "p " << p << ": " << covered << " of " << bounded;
  }
}

}  // namespace
