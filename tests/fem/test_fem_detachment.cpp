// The detachment time of the FEM (physics/observables.hpp) against a first-slip map of the bottom
// nodes kept here, node by node, from the contact state after every sliding step: the observer
// counts the nodes over ranks, this map takes each node's own record and the maximum over ranks.
// And the library's first-slip map (fem/first_slip_map.hpp): where the slip starts and how it
// crosses the plate.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/fem/first_slip_map.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

struct Detachment {
  FemRunResult run;
  double latestFirstSlip = std::numeric_limits<double>::quiet_NaN();  // over every node and rank
  long neverSlipped = 0;                                             // nodes, over ranks
};

// A run on through the mu_k window (well past the detachment: a later "every node slipped" must
// not move it), with each node's first step (time since the start of sliding) after which it had
// slipped or lost contact: the FEM's "every site" (docs/fem.md).
Detachment runWithFirstSlipMap(const Grading& grading) {
  const FemParameters q = test::coarse(10, 10, 2);
  PlateModel model(PETSC_COMM_WORLD, q, grading);
  std::vector<double> firstSlip(model.contact().nodes().size(), std::numeric_limits<double>::quiet_NaN());
  Detachment d;
  d.run = runPlateExperiment(model, [&](double tSliding, Vec) {
    const auto& nodes = model.contact().nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (std::isnan(firstSlip[i]) && nodes[i].everSlipped) firstSlip[i] = tSliding;
  });
  double latest = -INFINITY;
  long never = 0;
  for (double t : firstSlip) {
    if (std::isnan(t)) ++never;
    else latest = std::max(latest, t);
  }
  MPI_Allreduce(&latest, &d.latestFirstSlip, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(&never, &d.neverSlipped, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  return d;
}

}  // namespace

TEST(FemDetachment, IsTheLatestFirstSlipOfTheBottomNodes) {
  struct Case {
    std::string name;
    Grading grading;
  };
  const Case cases[] = {{"non-graded", test::noGrading()},
                        {"linear friction Delta 0.3", test::linear(GradedProperty::Friction, 0.3)}};
  for (const Case& c : cases) {
    const Detachment d = runWithFirstSlipMap(c.grading);
    const FrictionSummary& f = d.run.friction;
    PetscPrintf(PETSC_COMM_WORLD, "%-26s first slip %.6e s, detachment %.6e s, latest node %.6e s, peak %.6e s\n",
                c.name.c_str(), f.firstSlipTime, f.detachmentTime, d.latestFirstSlip, f.peakTime);
    ASSERT_TRUE(f.peakConfirmed) << c.name;
    EXPECT_EQ(d.neverSlipped, 0) << c.name << ": the peak is confirmed only once every node slipped";
    // The same step, so the same double: the observer's and the map's times are both t - t0 of it.
    EXPECT_EQ(f.detachmentTime, d.latestFirstSlip) << c.name;
    EXPECT_LE(f.firstSlipTime, f.detachmentTime) << c.name;
    ASSERT_TRUE(f.kineticComplete) << c.name;
    EXPECT_LT(f.detachmentTime, f.kineticFrom) << c.name << ": the run went on past it";
  }
}

// The first-slip map the results file stores: its earliest node is the observer's first slip (the
// same step); the slip starts on the trailing edge x = 0, where the moment of the top's force
// lowers the pressure (and, with Delta > 0, mu_s is lowest); with the friction gradient the front
// takes its time to cross (the paper's Figure 5), so the leading half slips later on average (on
// the non-graded plate the front crosses in about 10 us and a few nodes that first slide long after
// it blur the halves); the map of a plate sliding along x is mirror-symmetric in y. 2 ranks: the nodes
// gathered whole.
TEST(FemFirstSlipMap, StartsAtTheObserversFirstSlipOnTheTrailingEdge) {
  struct Case {
    std::string name;
    Grading grading;
    bool frontCrosses;  // the leading half slips later
  };
  const Case cases[] = {{"non-graded", test::noGrading(), false},
                        {"linear friction Delta 0.3", test::linear(GradedProperty::Friction, 0.3), true}};
  for (const Case& c : cases) {
    const FemParameters q = test::coarse(10, 10, 2);
    ASSERT_TRUE(q.measurement.firstSlipMap) << "first_slip is in the default -friction_observables";
    PlateModel model(PETSC_COMM_WORLD, q, c.grading);
    const FemRunResult run = runPlateExperiment(model, [](double, Vec) {});
    const FirstSlipMap map = gatherFirstSlipMap(model);
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    if (rank != 0) {
      EXPECT_TRUE(map.time.empty());
      continue;
    }
    ASSERT_EQ(map.nx, q.nx + 1);
    ASSERT_EQ(map.ny, q.ny + 1);
    ASSERT_EQ(map.time.size(), std::size_t(map.nx) * map.ny);
    double earliest = INFINITY, trailingHalf = 0, leadingHalf = 0;
    int earliestColumn = -1, slid = 0, trailingNodes = 0, leadingNodes = 0;
    for (int j = 0; j < map.ny; ++j)
      for (int i = 0; i < map.nx; ++i) {
        const double t = map.time[std::size_t(j) * map.nx + i];
        const double mirror = map.time[std::size_t(map.ny - 1 - j) * map.nx + i];
        EXPECT_EQ(std::isnan(t), std::isnan(mirror)) << c.name << " node " << i << "," << j;
        if (std::isnan(t)) continue;
        ++slid;
        EXPECT_LE(std::fabs(t - mirror), 2 * run.dt) << c.name << " node " << i << "," << j;
        if (t < earliest) earliest = t, earliestColumn = i;
        if (2 * i < map.nx - 1) trailingHalf += t, ++trailingNodes;
        if (2 * i > map.nx - 1) leadingHalf += t, ++leadingNodes;
      }
    PetscPrintf(PETSC_COMM_SELF, "%-26s first slip %.6e s at column %d; %d of %d nodes slid; mean %.6e s (x < L/2), %.6e s (x > L/2)\n",
                c.name.c_str(), earliest, earliestColumn, slid, map.nx * map.ny, trailingHalf / trailingNodes,
                leadingHalf / leadingNodes);
    EXPECT_EQ(earliest, run.friction.firstSlipTime) << c.name;
    EXPECT_EQ(earliestColumn, 0) << c.name << ": the slip starts on the trailing edge";
    EXPECT_GT(slid, map.nx * map.ny * 9 / 10) << c.name << ": the run went on through the kinetic window";
    if (c.frontCrosses) {
      EXPECT_LT(trailingHalf / trailingNodes, leadingHalf / leadingNodes) << c.name;
    }
  }
}
