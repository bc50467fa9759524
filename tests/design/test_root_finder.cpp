// The root finder's decisions on stand-in ensembles with a known mean curve f(x): an evaluation to
// half-width h "runs" n = (1.96 sd / h)^2 realisations (within the first batch and the cap) and
// reports f(x) plus a deterministic error inside its CI. No spring blocks: fast, and the answer is
// known exactly.
#include "gradfric/design/root_finder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace gradfric::design {
namespace {

struct StandIn {
  std::function<double(double)> mean;
  double sd = 0.004;  // of one realisation
  int count = 0;      // evaluations made
  long realisations = 0;

  EvaluateFunction function(const Problem& problem) {
    return [this, &problem](const std::vector<double>& x, double halfWidth, const std::string& phase) {
      const int n = std::clamp(static_cast<int>(std::ceil(std::pow(1.96 * sd / halfWidth, 2))), problem.firstBatch, problem.cap);
      const double h = 1.96 * sd / std::sqrt(double(n));
      Evaluation e;
      e.index = count++;
      e.phase = phase;
      e.x = x;
      e.realisations = n;
      e.value = mean(x[0]) + 0.4 * h * std::sin(37.0 * x[0]);  // an error well inside the CI
      e.ciLow = e.value - h;
      e.ciHigh = e.value + h;
      e.muStatic = e.value;
      realisations += n;
      return e;
    };
  }
};

Problem oneParameter(double lower, double upper, double target) {
  Problem p;
  p.free = {{"grading_delta", lower, upper}};
  p.target = target;
  p.tolerance = 0.002;
  p.coarse = 0.008;
  p.monitor = false;
  return p;
}

TEST(RootFinder, MonotoneFamilyMeetsTheTargetAndItsParameterCIHoldsTheRoot) {
  const Problem p = oneParameter(-0.4, 0.0, 0.8);
  StandIn model{[](double x) { return 0.93 + 0.7 * x - 0.5 * x * x; }};
  SearchLog log(MPI_COMM_WORLD, p);
  const SearchResult r = findRoot(model.function(p), p, log);
  ASSERT_EQ(r.status, Status::Found) << r.note;
  EXPECT_LE(r.design.ciLow, 0.8);
  EXPECT_GE(r.design.ciHigh, 0.8);
  EXPECT_LE(r.design.halfWidth(), p.tolerance);
  const double root = (-0.7 + std::sqrt(0.49 + 4 * 0.5 * 0.13)) / (-1.0);  // 0.93 + 0.7x - 0.5x^2 = 0.8
  ASSERT_TRUE(std::isfinite(r.slope));
  EXPECT_LE(r.parameterLow(), root);
  EXPECT_GE(r.parameterHigh(), root);
  EXPECT_LE(model.count, 10) << "regula falsi should need a handful of evaluations";
}

TEST(RootFinder, FarEvaluationsAreCoarseAndOnlyTheLastOnesRunToTheTolerance) {
  const Problem p = oneParameter(-0.4, 0.0, 0.8);
  StandIn model{[](double x) { return 0.93 + 0.7 * x; }, 0.012};  // noisy: +- 0.002 needs ~140 realisations
  SearchLog log(MPI_COMM_WORLD, p);
  ASSERT_EQ(findRoot(model.function(p), p, log).status, Status::Found);
  const auto& all = log.all();
  ASSERT_GE(all.size(), 3u);
  EXPECT_GT(all[0].halfWidth(), 2 * p.tolerance);  // the bounds: coarse
  EXPECT_GT(all[1].halfWidth(), 2 * p.tolerance);
  EXPECT_LE(all.back().halfWidth(), p.tolerance);  // the design: the tolerance
  EXPECT_LT(all[0].realisations + all[1].realisations, all.back().realisations / 4);
}

TEST(RootFinder, ScanFindsABracketInsideANonMonotoneFamily) {
  // Both bounds below the target, the middle above: the scan brackets it, one of the roots is found.
  const Problem p = oneParameter(-0.4, 0.4, 0.8);
  StandIn model{[](double x) { return 0.93 - 1.5 * x * x; }};
  SearchLog log(MPI_COMM_WORLD, p);
  const SearchResult r = findRoot(model.function(p), p, log);
  ASSERT_EQ(r.status, Status::Found) << r.note;
  const double root = std::sqrt(0.13 / 1.5);
  EXPECT_NEAR(std::fabs(r.design.x[0]), root, 0.01);
  EXPECT_TRUE(std::any_of(log.all().begin(), log.all().end(), [](const Evaluation& e) { return e.phase == "scan"; }));
}

TEST(RootFinder, UnreachableTargetReportsTheClosestAttainableValue) {
  const Problem p = oneParameter(-0.4, 0.0, 0.99);
  StandIn model{[](double x) { return 0.93 + 0.7 * x; }};
  SearchLog log(MPI_COMM_WORLD, p);
  const SearchResult r = findRoot(model.function(p), p, log);
  ASSERT_EQ(r.status, Status::Unreachable);
  EXPECT_EQ(r.design.x[0], 0.0);                 // the closest: the upper bound
  EXPECT_NEAR(r.design.value, 0.93, 0.002);      // its value, at the tolerance
  EXPECT_LE(r.design.halfWidth(), p.tolerance);
  EXPECT_EQ(exitCode(r.status), 4);
}

TEST(RootFinder, ACapBelowTheToleranceIsNotADesign) {
  Problem p = oneParameter(-0.4, 0.0, 0.8);
  p.cap = 8;  // the noise needs more than 8 realisations for +- 0.002
  StandIn model{[](double x) { return 0.93 + 0.7 * x; }, 0.02};
  SearchLog log(MPI_COMM_WORLD, p);
  const SearchResult r = findRoot(model.function(p), p, log);
  EXPECT_EQ(r.status, Status::NotConverged);
  EXPECT_EQ(exitCode(r.status), 5);
}

TEST(RootFinder, TheEvaluationBudgetIsKept) {
  Problem p = oneParameter(-0.4, 0.0, 0.8);
  p.maxEvaluations = 3;  // the bounds and one step
  StandIn model{[](double x) { return 0.93 + 0.7 * x + 3.0 * x * x * x; }};
  SearchLog log(MPI_COMM_WORLD, p);
  const SearchResult r = findRoot(model.function(p), p, log);
  EXPECT_TRUE(r.status == Status::Found || r.status == Status::NotConverged) << toString(r.status);
  int tried = 0;
  for (const auto& e : log.all()) tried += e.phase != "refine";
  EXPECT_LE(tried, 3);
}

TEST(RootFinder, FoundNeedsTheVerificationToHoldTheTarget) {
  SearchResult found;
  found.status = Status::Found;
  Evaluation verification;
  verification.ciLow = 0.8010;  // misses 0.8 from above
  verification.ciHigh = 0.8048;
  const SearchResult missed = settleOnVerification(found, verification, 0.8);
  EXPECT_EQ(missed.status, Status::NotVerified);
  EXPECT_EQ(exitCode(missed.status), 6);
  EXPECT_STREQ(toString(missed.status), "not_verified");
  verification.ciLow = 0.7990;  // holds it
  EXPECT_EQ(settleOnVerification(found, verification, 0.8).status, Status::Found);
  EXPECT_EQ(settleOnVerification(found, std::nullopt, 0.8).status, Status::Found);  // -design_verify false
  SearchResult unreachable;
  unreachable.status = Status::Unreachable;
  verification.ciLow = 0.8010;
  EXPECT_EQ(settleOnVerification(unreachable, verification, 0.8).status, Status::Unreachable);
}

}  // namespace
}  // namespace gradfric::design
