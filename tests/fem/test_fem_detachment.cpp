// The detachment time of the FEM (physics/observables.hpp) against a first-slip map of the bottom
// nodes kept here, node by node, from the contact state after every sliding step: the observer
// counts the nodes over ranks, this map takes each node's own record and the maximum over ranks.
#include <petscsection.h>
#include <petscsf.h>
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
