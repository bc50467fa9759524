// The plate's own weight (-fem_gravity, src/fem/terms/gravity.cpp), at g = 1e4 m/s^2 so that rho g H = 600 Pa
// is 6 % of p (the paper's plate otherwise):
//  - the pressed equilibrium carries p L^2 + rho g H L^2 on the plane: the static step to CG's
//    tolerance; the dynamic step (ramp and hold) adds the weight to what it settles to without it;
//  - the energy balance stays closed with the weight's work in it (dynamic and static step 1), and
//    that work is far above what the balance leaves open: without it the balance would fail;
//  - a constant friction 1 slides with the weight in its normal force;
//  - a weight six times the pressure slides to its peak without a false alarm of the blow-up monitor;
//  - g = 0 builds no layer (the driver's runs with -fem_gravity 0 and without it are compared bit for
//    bit by gravity_option.sh).
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/pressed_equilibrium.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

constexpr double kGravity = 1e4;  // [m/s^2]

// The term's setting, as the reader stores it (term_settings.hpp).
double gravityOf(const FemParameters& q) { return q.terms.get("gravity", 0.0); }

// rho g H / p: the weight against the pressure's load.
double weightShare(const FemParameters& q) {
  return q.plate.density * gravityOf(q) * q.plate.thickness / q.plate.pressure;
}

const Layer* findLayer(const PlateModel& model, const char* name) {
  for (const Layer* layer : model.layers())
    if (std::strcmp(layer->name(), name) == 0) return layer;
  return nullptr;
}

struct GravityRun {
  FemRunResult result;
  double weightWork = 0;  // energy the weight put in by the end [J] (minus its layer's work)
};

// Constant friction 1 on the reduced plate (test_fem_contact.cpp), sliding 2.5 t_s.
GravityRun slide(double gravity, bool staticStep) {
  FemParameters q = test::coarse(10, 10, 5);
  q.terms.set("gravity", gravity);
  q.staticPressureStep = staticStep;
  q.plate.muStatic = q.plate.muKinetic = 1.0;
  q.stopWhenKnown = false;
  q.slideTime = 2.5 * q.eq2PeakTime();
  q.monitorEvery = 50;
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  GravityRun run;
  run.result = runPlateExperiment(model);
  if (const Layer* weight = findLayer(model, "gravity")) {
    const LayerWork w = weight->work();
    run.weightWork = -sumOverRanks(PETSC_COMM_WORLD, w.rankShare);
  }
  return run;
}

// The worst |energy + dissipated - put in| over the samples of the sliding step, relative to the
// energy put in, and its largest absolute value [J].
void balance(const FemRunResult& r, double* relative, double* absolute) {
  *relative = *absolute = 0;
  for (std::size_t i = 0; i < r.energyTime.size(); ++i) {
    if (r.energyTime[i] < r.slideStart) continue;
    const double open = std::fabs(r.energy[i] + r.energyDissipated[i] - r.energyIn[i]);
    *relative = std::max(*relative, open / r.energyIn[i]);
    *absolute = std::max(*absolute, open);
  }
}

}  // namespace

TEST(FemGravity, OffBuildsNoLayerOnItsWeight) {
  FemParameters q = test::coarse(4, 4, 2);
  EXPECT_EQ(gravityOf(q), 0.0) << "off by default";
  {
    PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    EXPECT_EQ(findLayer(model, "gravity"), nullptr);
  }
  q.terms.set("gravity", 9.81);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  const Layer* weight = findLayer(model, "gravity");
  ASSERT_NE(weight, nullptr);
  EXPECT_NE(weight->describe().find("rho g H = 0.5886 Pa"), std::string::npos) << weight->describe();
  // Before the contact: the kinematic contact needs every other force.
  const auto& layers = model.layers();
  const auto at = [&](const char* name) { return std::find(layers.begin(), layers.end(), findLayer(model, name)); };
  EXPECT_LT(at("gravity"), at("contact"));
}

TEST(FemGravity, StaticPressedEquilibriumCarriesPressureAndWeight) {
  FemParameters q = test::coarse(12, 12, 3);
  q.terms.set("gravity", kGravity);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  // The lumped masses hold the plate's mass: the weight the layer applies is rho g H L^2.
  const double weight = model.mass().total() * gravityOf(q), pressure = q.plate.normalForce();
  EXPECT_NEAR(weight / (weightShare(q) * pressure), 1.0, 1e-12);
  OwnedVec X(model.createState());
  const PressedEquilibrium e = solvePressedEquilibrium(model, X);
  PetscPrintf(PETSC_COMM_WORLD,
              "static, g = %.0f m/s^2: %d CG iterations, residual %.2e, normal force %.12f (p L^2 + rho g H L^2), "
              "%.6f p L^2\n",
              gravityOf(q), e.iterations, e.residual, e.normalForce / (pressure + weight), e.normalForce / pressure);
  ASSERT_TRUE(e.holds) << e.why;
  EXPECT_EQ(e.open, 0);
  EXPECT_EQ(e.slipping, 0);
  EXPECT_NEAR(e.normalForce / (pressure + weight), 1.0, 1e-9);
  EXPECT_GT(e.normalForce / pressure - 1.0, 0.05) << "the weight is 6 % of the load";
}

// The dynamic step 1 with and without the weight: the plate is linear while it sticks, so the
// settled forces differ by the weight, the settling's residual transient (1e-4 of p L^2 on this
// mesh) cancelling but for the weight's own (it acts from t = 0, a sudden load, damped over 30 H/c_s).
TEST(FemGravity, DynamicRunCarriesTheWeightAndBalancesItsEnergy) {
  const GravityRun with = slide(kGravity, false), without = slide(0.0, false);
  FemParameters q = test::coarse(10, 10, 5);
  q.terms.set("gravity", kGravity);
  const double share = weightShare(q);
  const FemRunResult& r = with.result;
  double relative = 0, absolute = 0;
  balance(r, &relative, &absolute);
  double plateau = 0, count = 0;
  for (std::size_t i = 0; i < r.time.size(); ++i)
    if (r.time[i] >= 1.5 * q.eq2PeakTime()) {
      plateau += r.mu[i];
      count += 1;
    }
  plateau /= count;
  PetscPrintf(PETSC_COMM_WORLD,
              "dynamic, g = %.0f m/s^2: settled normal force %.9f p L^2 (without the weight %.9f, difference - rho g "
              "H/p = %.2e); energy balance worst %.3e of the energy put in (%.3e J), the weight's work %.3e J; "
              "constant friction 1: plateau %.5f p L^2 (1 + rho g H/p = %.5f)\n",
              gravityOf(q), r.settledNormalForce, without.result.settledNormalForce,
              r.settledNormalForce - without.result.settledNormalForce - share, relative, absolute, with.weightWork,
              plateau, 1 + share);
  EXPECT_NEAR(r.settledNormalForce - without.result.settledNormalForce, share, 1e-6);
  EXPECT_NEAR(r.settledNormalForce, 1 + share, 1e-3);
  // Measured 3.6e-6 (the weight's work is 1.7 % of the energy put in) and 1.1e-8 of p L^2.
  EXPECT_LT(relative, 1e-4);
  EXPECT_GT(with.weightWork, 20 * absolute) << "the balance would not close without the weight's work";
  EXPECT_EQ(without.weightWork, 0.0);
  ASSERT_GT(count, 100);
  EXPECT_NEAR(plateau, 1 + share, 1e-3) << "friction 1 of the normal force, weight included";
}

// After the static step the weight counts as loaded with the pressure (half m g u_z): the elastic
// energy it left in the plate.
TEST(FemGravity, StaticStepBalancesTheWeightsEnergy) {
  const GravityRun run = slide(kGravity, true);
  const FemRunResult& r = run.result;
  ASSERT_TRUE(r.staticPressureStep);
  double relative = 0, absolute = 0;
  balance(r, &relative, &absolute);
  PetscPrintf(PETSC_COMM_WORLD,
              "static step 1, g = %.0f m/s^2: settled normal force %.9f p L^2; energy balance worst %.3e of the energy "
              "put in (%.3e J), the weight's work %.3e J\n",
              kGravity, r.settledNormalForce, relative, absolute, run.weightWork);
  EXPECT_LT(relative, 1e-4);  // measured 9.9e-7
  EXPECT_GT(run.weightWork, 20 * absolute);
}

// A plate whose weight is most of its load (p = 100 Pa, rho g H = 600 Pa): the blow-up monitor
// scales with the load, so the run reaches its peak, mu_s (F over p L^2) the weight's share above
// the friction coefficient of the whole load.
TEST(FemGravity, WeightAboveThePressureSlidesWithoutAlarm) {
  Plate plate;
  plate.pressure = 100;
  plate.velocity = 1e-5;  // the peak ~30 steps after the start of sliding
  FemParameters q = test::coarse(8, 8, 2, plate);
  q.terms.set("gravity", kGravity);
  q.measurement.kinetic = false;  // stop at the confirmed peak
  const double load = 1 + weightShare(q);
  q.slideTime = 4 * load * q.eq2PeakTime();  // Eq. 2 with the load
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  FemRunResult r;
  EXPECT_NO_THROW(r = runPlateExperiment(model));
  PetscPrintf(PETSC_COMM_WORLD, "p = 100 Pa, rho g H = %.0f Pa: settled %.6f p L^2, mu_s %.5f = %.5f x the load\n",
              weightShare(q) * q.plate.pressure, r.settledNormalForce, r.friction.muStatic, r.friction.muStatic / load);
  EXPECT_NEAR(r.settledNormalForce, load, 1e-3 * load);
  EXPECT_TRUE(r.friction.peakConfirmed);
  EXPECT_GT(r.friction.muStatic / load, 0.8);
  EXPECT_LT(r.friction.muStatic / load, 1.02);
}
