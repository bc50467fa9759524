// The state law (physics/state_weakening_law.hpp, the FEM's default) in the FEM contact:
// * a contact node pulled at a constant fast speed, by penalty and by kinematic contact, feels the
//   law's strength at the state its slip gives, step by step: it weakens over D_c of slip, in
//   closed form;
// * on the reduced plate (10 x 10 x 5, non-graded), once the plate slides steadily at v = 10 v_c,
//   the global mu is Eq. 1's value at v (the law's steady state) within 1 %, with either contact.
#include "gradfric/fem/contact_kinematic.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

constexpr double kMuS = 1.0, kMuK = 0.6, kVc = 1e-4, kDc = 2.5e-8;

StateWeakening oneNode() {
  return StateWeakening::make({SiteLayout::PerSite, 1, {kMuS}, {kMuK}}, FrictionLawSettings{"state", kVc, kDc}, 1);
}

// The strength after sliding for t at constant speed v from theta = 0 (the law's closed form).
double strengthAfter(double v, double t) {
  const double theta = v * kDc / kVc * (1.0 - std::exp(-kVc * t / kDc));
  return kMuK + (kMuS - kMuK) * std::exp(-theta / kDc);
}

}  // namespace

TEST(FemStateLaw, APenaltyNodePulledAtConstantSpeedWeakensOverTheSlipLength) {
  StateWeakening law = oneNode();
  const PenaltyStiffness k{1.875e13, 1.875e13};
  const double v = 0.1, dt = 2e-8, gap = -1e-9;  // slip per step v dt = 2e-9 m = 0.08 D_c
  double ux = 1e-6, anchor = 0;                  // far beyond the elastic slip: slipping from the start
  bool slipping = false;
  for (int step = 0; step < 100; ++step) {
    const double slip = slipping ? v * dt : 0.0;
    const ContactTraction r = penaltyContact(k, law, 0, gap, ux, 0, anchor, 0, v, 0, slipping, slip, dt);
    ASSERT_EQ(r.state, ContactState::Slip);
    const double mu = std::fabs(r.tx) / r.pressure;
    // The first evaluation: a node that never slid holds up to mu_s; then the state follows the slip.
    const double expected = step == 0 ? kMuS : strengthAfter(v, step * dt);
    ASSERT_NEAR(mu, expected, 1e-12) << "step " << step;
    law.commit();
    anchor = r.anchorX;
    slipping = true;
    ux += v * dt;
  }
  // 99 steps of 0.08 D_c: 7.9 D_c of slip, the strength within 0.1 % of Delta mu from mu_k.
  EXPECT_LT(law.strengthAt(0, law.state[0]) - kMuK, 1e-3 * (kMuS - kMuK));
  // At one D_c of slip (12.5 steps) it had lost 1 - 1/e of Delta mu.
  EXPECT_NEAR((strengthAfter(v, kDc / v) - kMuK) / (kMuS - kMuK), std::exp(-1.0), 1e-3);
}

TEST(FemStateLaw, AKinematicNodeSlidingAtConstantSpeedWeakensTheSameWay) {
  StateWeakening law = oneNode();
  const double v = 0.1, dt = 2e-8, mass = 1e-9;
  const double velocity[3] = {v, 0, 0}, pulled[3] = {1e6, 0, -1e3};  // driven far beyond any friction
  for (int step = 1; step <= 50; ++step) {
    const KinematicContactForce r = kinematicContact(law, 0, mass, dt, 0.0, velocity, pulled, v * dt);
    ASSERT_EQ(r.state, ContactState::Slip);
    ASSERT_NEAR(r.strength, strengthAfter(v, step * dt), 1e-12) << "step " << step;
    ASSERT_NEAR(std::fabs(r.fx) / r.fn, r.strength, 1e-12);
    law.commit();
  }
}

TEST(FemStateLaw, NonGradedSteadySlidingIsEquationOneAtTheSliderSpeed) {
  for (ContactMethod method : {ContactMethod::Kinematic, ContactMethod::Penalty}) {
    FemParameters q = test::coarse(10, 10, 5);
    ASSERT_EQ(q.frictionLaw.name, "state") << "the default law";
    q.contactMethod = method;
    q.stopWhenKnown = false;
    const double ts = q.eq2PeakTime();
    q.slideTime = 5.0 * ts;
    const double eq1 = q.plate.muKinetic + (q.plate.muStatic - q.plate.muKinetic) *
                                               std::exp(-q.plate.velocity / q.frictionLaw.criticalVelocity);
    PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    const FemRunResult r = runPlateExperiment(model);
    ASSERT_TRUE(r.friction.peakConfirmed);
    double sum = 0, lo = 1e300, hi = -1e300;
    int count = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i)
      if (r.time[i] >= 3.5 * ts) {
        sum += r.mu[i];
        lo = std::min(lo, r.mu[i]);
        hi = std::max(hi, r.mu[i]);
        ++count;
      }
    ASSERT_GT(count, 100);
    const double steady = sum / count;
    PetscPrintf(PETSC_COMM_WORLD,
                "%s: mu_s %.6f, steady mu over 3.5-5 t_s %.6f (range %.6f-%.6f), Eq. 1 at v %.6f (%+.3f %%)\n",
                contactMethodName(method), r.friction.muStatic, steady, lo, hi, eq1, 100 * (steady / eq1 - 1));
    EXPECT_NEAR(steady / eq1, 1.0, 0.01) << contactMethodName(method);
    EXPECT_GT(r.friction.muStatic, 1.2 * eq1) << "a static peak above the kinetic level";
  }
}

TEST(FemStateLaw, ConstantFrictionSlidesOnAPlateauAtItsPeak) {
  // mu_s = mu_k: no weakening, so no static peak above the sliding level (the flutter threshold of
  // a solid sliding on a rigid plane is mu = 1: 0.6 is below it, 1 on it).
  for (double mu : {0.6, 1.0}) {
    Plate plate;
    plate.muStatic = plate.muKinetic = mu;
    FemParameters q = test::coarse(10, 10, 5, plate);
    q.stopWhenKnown = false;
    const double ts = q.eq2PeakTime();
    q.slideTime = 5.0 * ts;
    PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    const FemRunResult r = runPlateExperiment(model);
    double sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i)
      if (r.time[i] >= 3.5 * ts) sum += r.mu[i], ++count;
    ASSERT_GT(count, 100);
    const double plateau = sum / count;
    PetscPrintf(PETSC_COMM_WORLD, "constant mu %.1f: peak %.6f, plateau over 3.5-5 t_s %.6f (%+.3f %%)\n", mu,
                r.friction.muStatic, plateau, 100 * (plateau / r.friction.muStatic - 1));
    EXPECT_NEAR(plateau / r.friction.muStatic, 1.0, 0.01) << "mu " << mu;
    EXPECT_NEAR(plateau, mu, 0.01 * mu);
  }
}
