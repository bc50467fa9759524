// The sweep: Cartesian product in a fixed order, the non-graded reference of every point, and
// the pending-task list (finished tasks skipped, expensive points first).
#include "gradfric/campaign/sweep.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace gradfric;
using namespace gradfric::campaign;

namespace {
SweepPoint basePoint() {
  SweepPoint b;
  b.profile = "linear";
  b.property = "friction";
  b.delta = 0.1;
  b.theta = 0.0;
  b.sigma = b.sigmaKinetic = 0.028;
  return b;
}
}  // namespace

TEST(EnsembleSweep, NoListsGiveTheBasePointAlone) {
  const Sweep s = buildSweep({}, basePoint());
  ASSERT_EQ(s.points.size(), 1u);
  EXPECT_TRUE(s.axes.empty());
  EXPECT_EQ(s.points[0].delta, 0.1);
  EXPECT_EQ(s.reference[0], -1);  // graded, and no non-graded point to compare with
}

TEST(EnsembleSweep, CartesianProductDeltaInnermost) {
  SweepLists l;
  l.theta = {0.0, 90.0};
  l.delta = {-0.2, 0.0, 0.2};
  const Sweep s = buildSweep(l, basePoint());
  ASSERT_EQ(s.points.size(), 6u);
  EXPECT_EQ(s.axes, (std::vector<std::string>{"theta", "delta"}));
  const double expectedTheta[] = {0, 0, 0, 90, 90, 90};
  const double expectedDelta[] = {-0.2, 0, 0.2, -0.2, 0, 0.2};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(s.points[i].theta, expectedTheta[i]) << i;
    EXPECT_EQ(s.points[i].delta, expectedDelta[i]) << i;
    EXPECT_EQ(s.points[i].sigma, 0.028);
  }
  // Each point is compared with the Delta = 0 point of its own angle.
  const int expectedReference[] = {1, 1, 1, 4, 4, 4};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(s.reference[i], expectedReference[i]) << i;
}

TEST(EnsembleSweep, SigmaSetsBothDispersionsAndPropertiesShareTheReference) {
  SweepLists l;
  l.sigma = {0.0, 0.05};
  const Sweep s = buildSweep(l, basePoint());
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[1].sigma, 0.05);
  EXPECT_EQ(s.points[1].sigmaKinetic, 0.05);

  SweepLists m;
  m.property = {"E", "friction"};
  m.delta = {0.0, 0.3};
  const Sweep t = buildSweep(m, basePoint());
  ASSERT_EQ(t.points.size(), 4u);
  EXPECT_EQ(t.points[1].property, "E");
  EXPECT_EQ(t.reference[1], 0);
  EXPECT_EQ(t.reference[3], 2);
  // A profile "none" point is non-graded whatever its Delta: it is its own reference.
  SweepLists n;
  n.profile = {"none", "triangular"};
  const Sweep u = buildSweep(n, basePoint());
  EXPECT_EQ(u.reference[0], 0);
  EXPECT_EQ(u.reference[1], 0);
}

TEST(EnsembleSweep, GradingOfAPoint) {
  SweepPoint p = basePoint();
  p.profile = "triangular";
  p.property = "E";
  p.delta = -0.2;
  const Grading g = gradingOf(p, 7);
  EXPECT_EQ(g.profile, GradingProfile::Triangular);
  EXPECT_EQ(g.property, GradedProperty::YoungsModulus);
  EXPECT_EQ(g.delta, -0.2);
  EXPECT_EQ(g.bands, 7);
  p.property = "both";
  p.profile = "none";
  EXPECT_EQ(gradingOf(p, 10).property, GradedProperty::Both);
  EXPECT_FALSE(gradingOf(p, 10).active());
}

TEST(EnsembleSweep, PendingTasksSkipFinishedAndStartWithTheExpensive) {
  SweepLists l;
  l.delta = {0.0, 0.4, -0.1};
  const Sweep s = buildSweep(l, basePoint());
  const int R = 2;
  std::vector<unsigned char> finished(3 * R, 0);
  finished[1 * R + 0] = 1;  // (point 1, realisation 0) done
  const auto tasks = pendingTasks(s, R, finished);
  ASSERT_EQ(tasks.size(), 5u);
  EXPECT_EQ(tasks[0].point, 1);  // |Delta| = 0.4 first
  EXPECT_EQ(tasks[0].realisation, 1);
  EXPECT_EQ(tasks[1].point, 2);  // then |Delta| = 0.1
  EXPECT_EQ(tasks[3].point, 0);  // the non-graded point last
  std::set<std::pair<int, int>> seen;
  for (const auto& t : tasks) seen.insert({t.point, t.realisation});
  EXPECT_EQ(seen.size(), 5u);
  EXPECT_EQ(seen.count({1, 0}), 0u);
  EXPECT_EQ(pendingTasks(s, R, {}).size(), 6u);
  EXPECT_GT(estimatedCost(s.points[1]), estimatedCost(s.points[2]));
  EXPECT_EQ(estimatedCost(s.points[0]), 1.0);
}
