// The slip (state) length of a friction law (physics/slip_state_law.hpp) on its own: without a
// slip length it is the law itself bit for bit; steady sliding at v gives the law's value (Eq. 1);
// a velocity step relaxes over D_c of slip, exactly, whatever the steps; a site that sticks keeps
// its strength (mu_s until it first slides, its weakened strength after).
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/slip_state_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;

namespace {

constexpr double kMuS = 1.0, kMuK = 0.6, kVc = 1e-4;

ExponentialVelocityWeakening equationOne() {
  FrictionSites sites{SiteLayout::PerSite, 3, {kMuS, 0.8, 1.2}, {kMuK, 0.5, 0.7}};
  FrictionLawSettings settings;
  settings.name = "exponential";
  settings.criticalVelocity = kVc;
  return ExponentialVelocityWeakening::make(sites, settings);
}

double eq1(double staticStrength, double kineticStrength, double v) {
  return kineticStrength + (staticStrength - kineticStrength) * std::exp(-v / kVc);
}

// Slides site 0 at speed v for `slip` [m] in n equal steps, committing after each.
void slide(WithSlipLength<ExponentialVelocityWeakening>& law, double v, double slip, int n) {
  for (int i = 0; i < n; ++i) {
    law.contactStrength(0, v, slip / n, 0.0, true);
    law.commit();
  }
}

}  // namespace

TEST(SlipStateLaw, WithoutSlipLengthItIsTheLawBitForBit) {
  const ExponentialVelocityWeakening plain = equationOne();
  const auto law = WithSlipLength<ExponentialVelocityWeakening>::make(plain, 0.0, 3);
  EXPECT_FALSE(law.hasState());
  for (int site = 0; site < 3; ++site)
    for (double v : {0.0, 1e-7, 3e-5, 1e-4, 1e-3, 0.1}) {
      const double s = plain.sites.staticAt(site), k = plain.sites.kineticAt(site);
      EXPECT_EQ(law.strengthAfter(site, v, 1e-6, true), plain.slidingStrength(s, k, v));  // bitwise
      EXPECT_EQ(law.strengthAfter(site, v, 1e-6, false), s);  // a sticking site holds up to mu_s
    }
  // The same for the SBM's Coulomb law: the wrapper with D_c = 0 is the law.
  const CoulombStickSlip coulomb = CoulombStickSlip::make({SiteLayout::Uniform, 1, {2.0}, {1.5}}, {});
  const auto wrapped = WithSlipLength<CoulombStickSlip>::make(coulomb, 0.0, 4);
  for (int site = 0; site < 4; ++site) {
    EXPECT_EQ(wrapped.strengthAfter(site, 0.3, 1.0, true), 1.5);
    EXPECT_EQ(wrapped.strengthAfter(site, 0.3, 1.0, false), 2.0);
  }
}

TEST(SlipStateLaw, EverySiteStartsAtItsStaticStrengthAndStickingKeepsIt) {
  auto law = WithSlipLength<ExponentialVelocityWeakening>::make(equationOne(), 1e-8, 3);
  EXPECT_TRUE(law.hasState());
  EXPECT_EQ(law.strength[0], 1.0);
  EXPECT_EQ(law.strength[1], 0.8);
  EXPECT_EQ(law.strength[2], 1.2);
  // Sticking (or sliding without slip): no change, mu_s for a site that never slid.
  EXPECT_EQ(law.strengthAfter(1, 1e-3, 1e-9, false), 0.8);
  EXPECT_EQ(law.strengthAfter(1, 1e-3, 0.0, true), 0.8);
  // Nothing changes until commit.
  const double next = law.strengthAfter(0, 1e-3, 1e-8, true);
  EXPECT_LT(next, 1.0);
  EXPECT_EQ(law.contactStrength(0, 1e-3, 1e-8, 0.0, true), next);  // pending, not yet the state
  EXPECT_EQ(law.strength[0], 1.0);
  law.commit();
  EXPECT_EQ(law.strength[0], next);
}

TEST(SlipStateLaw, SteadySlidingGivesEquationOne) {
  for (double v : {1e-5, 1e-4, 1e-3, 1e-2}) {
    auto law = WithSlipLength<ExponentialVelocityWeakening>::make(equationOne(), 1e-8, 3);
    slide(law, v, 50e-8, 500);  // 50 D_c
    EXPECT_NEAR(law.strength[0], eq1(kMuS, kMuK, v), 1e-15) << "v = " << v;
  }
  // The paper's case: v = 10 v_c gives 0.60002 (Eq. 1), not mu_k.
  auto law = WithSlipLength<ExponentialVelocityWeakening>::make(equationOne(), 1e-8, 3);
  slide(law, 1e-3, 1e-6, 1000);
  EXPECT_NEAR(law.strength[0], 0.6 + 0.4 * std::exp(-10.0), 1e-15);
}

TEST(SlipStateLaw, AVelocityStepRelaxesOverTheSlipLength) {
  const double dc = 2e-8;
  auto law = WithSlipLength<ExponentialVelocityWeakening>::make(equationOne(), dc, 3);
  slide(law, 1e-3, 100 * dc, 100);  // steady at v = 10 v_c
  const double before = law.strength[0], after = eq1(kMuS, kMuK, 5e-5);
  // Step down to v = 0.5 v_c: after a slip D_c the distance to the new steady value is 1/e of
  // the step, whether the slip is taken in one step or in 1000.
  auto coarse = law, fine = law;
  slide(coarse, 5e-5, dc, 1);
  slide(fine, 5e-5, dc, 1000);
  EXPECT_NEAR((coarse.strength[0] - after) / (before - after), std::exp(-1.0), 1e-12);
  EXPECT_NEAR((fine.strength[0] - after) / (before - after), std::exp(-1.0), 1e-12);
  // And after 3 D_c more, 1/e^4: the strength heals towards Eq. 1 at the slow speed by slipping.
  slide(fine, 5e-5, 3 * dc, 7);
  EXPECT_NEAR((fine.strength[0] - after) / (before - after), std::exp(-4.0), 1e-12);
  EXPECT_GT(fine.strength[0], before);
}

TEST(SlipStateLaw, ASiteThatStopsKeepsItsWeakenedStrength) {
  auto law = WithSlipLength<ExponentialVelocityWeakening>::make(equationOne(), 1e-8, 3);
  slide(law, 1e-3, 1e-6, 100);
  const double weakened = law.strength[0];
  EXPECT_NEAR(weakened, 0.60002, 1e-5);
  // Stuck for many steps: no slip, no healing (the slip law; Eq. 1 alone would be back at mu_s).
  for (int i = 0; i < 1000; ++i) {
    law.contactStrength(0, 0.0, 0.0, 0.0, false);
    law.commit();
  }
  EXPECT_EQ(law.strength[0], weakened);
  // Other sites are untouched.
  EXPECT_EQ(law.strength[1], 0.8);
}

// Healing only (the FEM's default): the strength falls with the slip rate at once, exactly as
// the law, and only its rise back as the site slows down takes the slip D_c.
TEST(SlipStateLaw, HealingOnlyWeakensAtOnceAsTheLawAndHealsOverTheSlipLength) {
  const ExponentialVelocityWeakening plain = equationOne();
  const double dc = 1e-8;
  auto law = WithSlipLength<ExponentialVelocityWeakening>::make(plain, dc, 3, true);
  // From mu_s, sliding at any speed gives the law's value at once, bit for bit, whatever the slip.
  for (double v : {1e-6, 1e-4, 1e-3})
    for (double slip : {0.0, 1e-12, 1e-6})
      EXPECT_EQ(law.strengthAfter(0, v, slip, true), plain.slidingStrength(kMuS, kMuK, v));
  slide(law, 1e-3, 1e-11, 1);
  EXPECT_EQ(law.strength[0], plain.slidingStrength(kMuS, kMuK, 1e-3));
  // Slowing down to v_c / 2: the strength rises towards Eq. 1 there over D_c, exactly.
  const double before = law.strength[0], after = eq1(kMuS, kMuK, 5e-5);
  auto coarse = law, fine = law;
  slide(coarse, 5e-5, dc, 1);
  slide(fine, 5e-5, dc, 100);
  EXPECT_NEAR((coarse.strength[0] - after) / (before - after), std::exp(-1.0), 1e-12);
  EXPECT_NEAR((fine.strength[0] - after) / (before - after), std::exp(-1.0), 1e-12);
  // Speeding up again: back to the law's value at once.
  slide(fine, 1e-3, 1e-12, 1);
  EXPECT_EQ(fine.strength[0], plain.slidingStrength(kMuS, kMuK, 1e-3));
  // Stopped (sticking): it keeps its weakened strength; steady sliding gives Eq. 1.
  for (int i = 0; i < 100; ++i) {
    fine.contactStrength(0, 0.0, 0.0, 0.0, false);
    fine.commit();
  }
  EXPECT_EQ(fine.strength[0], plain.slidingStrength(kMuS, kMuK, 1e-3));
  EXPECT_NEAR(fine.strength[0], 0.6 + 0.4 * std::exp(-10.0), 1e-15);
}
