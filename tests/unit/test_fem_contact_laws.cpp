// The friction laws in the FEM's contact, node by node (contact_penalty.hpp, contact_kinematic.hpp;
// no PETSc): a kinematic node pressed and pulled sticks or slides exactly at mu_s and slides at
// Eq. 1's mu(v); Eq. 1 without a slip length is the plain law bit for bit with both contacts
// (physics/slip_state_law.hpp); the state law (physics/state_weakening_law.hpp) weakens a pulled
// node over D_c of slip in closed form. The same laws in a running plate: tests/fem
// (test_fem_contact.cpp, test_fem_slip_state.cpp, test_fem_state_law.cpp).
#include "gradfric/fem/contact_kinematic.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/physics/exponential_law.hpp"
#include "gradfric/physics/slip_state_law.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

// Eq. 1 at one site.
ExponentialVelocityWeakening oneSiteLaw(double muS, double muK, double vC) {
  FrictionSites sites;
  sites.layout = SiteLayout::PerSite;
  sites.columns = 1;
  sites.staticStrength = {muS};
  sites.kineticStrength = {muK};
  FrictionLawSettings settings;
  settings.criticalVelocity = vC;
  return ExponentialVelocityWeakening::make(sites, settings);
}

// Eq. 1 at two sites of different strengths (v_c 0.1 mm/s).
ExponentialVelocityWeakening equationOne() {
  FrictionSites sites{SiteLayout::PerSite, 2, {1.0, 0.9}, {0.6, 0.55}};
  FrictionLawSettings settings;
  settings.criticalVelocity = 1e-4;
  return ExponentialVelocityWeakening::make(sites, settings);
}

// The state law's node: Eq. 1's strengths and v_c, the default weakening length D_c.
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

TEST(FemContact, KinematicNodePressedAndPulledSticksOrSlidesExactlyAtMuS) {
  const double muS = 0.8, muK = 0.5, m = 3e-11, dt = 4e-8, press = 2.5e-5;
  const ExponentialVelocityWeakening law = oneSiteLaw(muS, muK, 1e-4);
  const double v[3] = {0, 0, 0};
  for (double ratio : {0.0, 0.5, 1.0 - 1e-9, 1.0 + 1e-9, 1.5}) {
    const double pull = ratio * muS * press;
    const double aFree[3] = {pull / m, 0, -press / m};  // pressed with press, pulled with pull, at rest on the plane
    const KinematicContactForce r = kinematicContact(law, 0, m, dt, 0.0, v, aFree);
    EXPECT_NEAR(r.fn, press, 1e-12 * press) << "the normal force stops the node exactly";
    if (ratio <= 1.0) {
      EXPECT_EQ(r.state, ContactState::Stick) << "pulled with " << ratio << " mu_s p";
      EXPECT_NEAR(r.fx, -pull, 1e-12 * press) << "sticking: the force that stops it, exactly";
    } else {
      EXPECT_EQ(r.state, ContactState::Slip) << "pulled with " << ratio << " mu_s p";
      EXPECT_NEAR(r.fx, -muS * press, 1e-12 * press) << "starting to slide (v = 0): mu(0) p = mu_s p";
    }
    EXPECT_EQ(r.fy, 0.0);
  }
  // Sliding at 10 v_c and pulled on: the force is Eq. 1's mu(v) f_n against the motion, from the
  // same law object.
  const double vs[3] = {1e-3, 0, 0};
  const double aPulled[3] = {2 * muS * press / m, 0, -press / m};
  const KinematicContactForce s = kinematicContact(law, 0, m, dt, 0.0, vs, aPulled);
  ASSERT_EQ(s.state, ContactState::Slip);
  EXPECT_NEAR(s.fx, -law.slidingStrength(muS, muK, 1e-3) * press, 1e-12 * press);
  EXPECT_NEAR(-s.fx / press, muK + (muS - muK) * std::exp(-10.0), 1e-12);
  // Sliding and driven by less than mu_s f_n but more than its sliding friction: it slides on (a
  // moving node stops only if the friction it feels can stop it within the step).
  const double aDriven[3] = {0.7 * muS * press / m, 0, -press / m};
  const KinematicContactForce on = kinematicContact(law, 0, m, dt, 0.0, vs, aDriven);
  EXPECT_EQ(on.state, ContactState::Slip);
  EXPECT_NEAR(on.fx, -law.slidingStrength(muS, muK, 1e-3) * press, 1e-12 * press);
  // Sliding slowly with a small drive: its friction stops it, and it sticks.
  const double slow[3] = {1e-6, 0, 0};
  const double aSmall[3] = {0.1 * muS * press / m, 0, -press / m};
  EXPECT_EQ(kinematicContact(law, 0, m, dt, 0.0, slow, aSmall).state, ContactState::Stick);
  // Above the plane and not reaching it within the step: no force.
  const double aFree[3] = {0, 0, -press / m};
  const KinematicContactForce open = kinematicContact(law, 0, m, dt, 1e-6, v, aFree);
  EXPECT_EQ(open.state, ContactState::Open);
  EXPECT_EQ(open.fn, 0.0);
}

TEST(FemSlipState, WithoutSlipLengthTheContactIsThePlainLawBitForBit) {
  const ExponentialVelocityWeakening plain = equationOne();
  auto wrapped = WithSlipLength<ExponentialVelocityWeakening>::make(plain, 0.0, 2);
  const PenaltyStiffness k{1.875e13, 1.875e13};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e-8, 1e-8), vel(-3e-3, 3e-3);
  for (int i = 0; i < 2000; ++i) {
    const int site = i % 2;
    const double gap = u(rng), ux = u(rng), uy = u(rng), ax = u(rng), ay = u(rng), vx = vel(rng), vy = vel(rng);
    for (bool slipping : {false, true}) {
      const ContactTraction a = penaltyContact(k, plain, site, gap, ux, uy, ax, ay, vx, vy, slipping);
      const ContactTraction b = penaltyContact(k, wrapped, site, gap, ux, uy, ax, ay, vx, vy, slipping, 1e-9);
      ASSERT_EQ(a.tx, b.tx);
      ASSERT_EQ(a.ty, b.ty);
      ASSERT_EQ(a.pressure, b.pressure);
      ASSERT_EQ(a.anchorX, b.anchorX);
      ASSERT_EQ(a.state, b.state);
    }
    const double v[3] = {vx, vy, 0.0}, aFree[3] = {1e3 * vel(rng), 1e3 * vel(rng), 1e3 * vel(rng)};
    const KinematicContactForce a = kinematicContact(plain, site, 1e-9, 2e-8, gap, v, aFree);
    const KinematicContactForce b = kinematicContact(wrapped, site, 1e-9, 2e-8, gap, v, aFree, 1e-9);
    ASSERT_EQ(a.fn, b.fn);
    ASSERT_EQ(a.fx, b.fx);
    ASSERT_EQ(a.fy, b.fy);
    ASSERT_EQ(a.state, b.state);
  }
}

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
