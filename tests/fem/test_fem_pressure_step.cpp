// The static pressure step (-fem_pressure_step static, pressed_equilibrium.hpp) against the
// dynamic one: the pressed equilibrium is the state the ramp and hold settles to, given time.
//  - its normal force is p L^2 to the CG tolerance, every bottom node in contact and sticking,
//    the plate at rest;
//  - the dynamic step with a long hold (8 x the default 10 H/c_s, the transient damped out)
//    reaches the same displacement field and the same mu_s; the default hold keeps a residual
//    transient (measured on 20 x 20 x 5: mu_s 0.910701 dynamic, 0.907879 static and long hold);
//  - where the linear solution does not hold (a plate that would slip at its edges under the
//    Poisson expansion) the dynamic step runs instead, and the run says so.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/fem/pressed_equilibrium.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

struct SteppedRun {
  FemRunResult result;
  std::vector<double> firstState;  // this rank's state after the first sliding step
};

SteppedRun run(FemParameters q) {
  q.measurement.kinetic = false;  // stop at the confirmed peak
  q.slideTime = defaultSlideTime(q.eq2PeakTime(), q.measurement);  // the cap of a mu_s-only run
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  SteppedRun out;
  out.result = runPlateExperiment(model, [&](double, Vec X) {
    if (!out.firstState.empty()) return;
    PetscInt n = 0;
    const PetscScalar* x = nullptr;
    VecGetLocalSize(X, &n);
    VecGetArrayRead(X, &x);
    out.firstState.assign(x, x + n);
    VecRestoreArrayRead(X, &x);
  });
  return out;
}

FemParameters scene() {
  FemParameters q = test::coarse(12, 12, 3);
  return q;
}

}  // namespace

TEST(FemPressureStep, PressedEquilibriumIsExactAtRestAndSticking) {
  FemParameters q = scene();
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  OwnedVec X(model.createState());
  const PressedEquilibrium e = solvePressedEquilibrium(model, X);
  const double force = model.params().plate.normalForce();
  PetscPrintf(PETSC_COMM_WORLD, "static: %d CG iterations, residual %.2e, normal force %.15f p L^2\n", e.iterations,
              e.residual, e.normalForce / force);
  ASSERT_TRUE(e.holds) << e.why;
  EXPECT_LT(e.residual, 1e-11);
  EXPECT_NEAR(e.normalForce / force, 1.0, 1e-9);
  EXPECT_EQ(e.open, 0);
  EXPECT_EQ(e.slipping, 0);
  EXPECT_EQ(model.kineticEnergy(X), 0.0);
  const ContactTotals t = model.contactTotals();
  EXPECT_EQ(t.stick, t.nodes);
}

TEST(FemPressureStep, DynamicStepWithALongHoldReachesTheStaticState) {
  FemParameters dynamic = scene();
  dynamic.staticPressureStep = false;
  dynamic.settleTime *= 8;
  FemParameters fixed = scene();
  fixed.staticPressureStep = true;
  const SteppedRun d = run(dynamic), s = run(fixed);
  ASSERT_TRUE(s.result.staticPressureStep);
  ASSERT_FALSE(d.result.staticPressureStep);
  ASSERT_EQ(d.firstState.size(), s.firstState.size());
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < s.firstState.size(); i += 6)
    for (int k = 0; k < 3; ++k) {  // displacements after the first sliding step
      largest = std::max(largest, std::fabs(s.firstState[i + k]));
      difference = std::max(difference, std::fabs(s.firstState[i + k] - d.firstState[i + k]));
    }
  double all[2] = {largest, difference}, most[2];
  MPI_Allreduce(all, most, 2, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  PetscPrintf(PETSC_COMM_WORLD,
              "dynamic (hold 8 x default) vs static: displacement difference %.3e of its largest value; settled normal "
              "force %.9f vs %.9f; mu_s %.9f vs %.9f (static: %d CG iterations)\n",
              most[1] / most[0], d.result.settledNormalForce, s.result.settledNormalForce, d.result.friction.muStatic,
              s.result.friction.muStatic, s.result.pressureIterations);
  // Measured on this mesh: 2.2e-12 and mu_s equal to 9 digits.
  EXPECT_LT(most[1] / most[0], 1e-8);
  EXPECT_NEAR(d.result.settledNormalForce, s.result.settledNormalForce, 1e-7);
  EXPECT_NEAR(d.result.friction.muStatic / s.result.friction.muStatic, 1.0, 1e-7);
  EXPECT_TRUE(s.result.friction.peakConfirmed);
}

TEST(FemPressureStep, FallsBackToTheDynamicStepWhereTheEdgesWouldSlip) {
  Plate slippery;
  slippery.muStatic = 0.002;  // the Poisson expansion under p then slips the edge nodes
  slippery.muKinetic = 0.001;
  FemParameters q = test::coarse(12, 12, 3, slippery);
  q.staticPressureStep = true;
  q.measurement.kinetic = false;  // stop at the confirmed peak
  q.slideTime = defaultSlideTime(q.eq2PeakTime(), q.measurement);  // the cap of a mu_s-only run
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  OwnedVec X(model.createState());
  const PressedEquilibrium e = solvePressedEquilibrium(model, X);
  PetscPrintf(PETSC_COMM_WORLD, "mu_s 0.002: %s\n", e.why.c_str());
  EXPECT_FALSE(e.holds);
  EXPECT_GT(e.slipping, 0);
  PetscReal norm = 1;
  VecNorm(X, NORM_INFINITY, &norm);
  EXPECT_EQ(norm, 0.0) << "the state was not reset for the dynamic step";
}
