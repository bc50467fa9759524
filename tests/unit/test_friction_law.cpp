// The friction laws' pointwise functions: the code both spring-block kernels and the FEM contact
// run (they call exactly these: StaticThreshold::holds, slidingStrength, FrictionSites::slot).
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/sbm/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gradfric;

namespace {

FrictionSites uniformSites(double staticStrength, double kineticStrength) {
  return {SiteLayout::Uniform, 1, {staticStrength}, {kineticStrength}};
}

}  // namespace

TEST(FrictionLaw, StaticThresholdHoldsUpToTheStaticStrengthExactly) {
  // Compared in squares: |F| = mu_s F_n holds, the next double above does not.
  const double threshold = 2.0;
  EXPECT_TRUE(CoulombStickSlip::holds(threshold * threshold, threshold));
  EXPECT_FALSE(CoulombStickSlip::holds(std::nextafter(threshold * threshold, 10.0), threshold));
  EXPECT_TRUE(ExponentialVelocityWeakening::holds(0.0, threshold));
  EXPECT_FALSE(ExponentialVelocityWeakening::holds(4.0001, threshold));
}

TEST(FrictionLaw, CoulombSlidesAtTheKineticStrengthWhateverTheSpeed) {
  const CoulombStickSlip law = CoulombStickSlip::make(uniformSites(1.0, 0.6), {});
  for (double v : {0.0, 1e-9, 1.0, 1e6}) EXPECT_EQ(law.slidingStrength(1.0, 0.6, v), 0.6);
}

TEST(FrictionLaw, ExponentialWeakeningOfEquationOne) {
  FrictionLawSettings settings;
  settings.name = "exponential";
  settings.criticalVelocity = 1e-4;
  const ExponentialVelocityWeakening law = ExponentialVelocityWeakening::make(uniformSites(1.0, 0.6), settings);
  EXPECT_EQ(law.criticalVelocity, 1e-4);
  EXPECT_DOUBLE_EQ(law.slidingStrength(1.0, 0.6, 0.0), 1.0);  // Eq. 1 at rest: mu_s
  EXPECT_NEAR(law.slidingStrength(1.0, 0.6, 1e-4), 0.6 + 0.4 / M_E, 1e-15);
  EXPECT_NEAR(law.slidingStrength(1.0, 0.6, 1.0), 0.6, 1e-12);  // v >> v_c: mu_k
  EXPECT_GT(law.slidingStrength(1.0, 0.6, 1e-5), law.slidingStrength(1.0, 0.6, 2e-5));
  // In force units (the SBM): F_n mu(v) from the strengths mu_s F_n, mu_k F_n.
  const double fn = 3.0;
  EXPECT_NEAR(law.slidingStrength(fn * 1.0, fn * 0.6, 2e-4), fn * (0.6 + 0.4 * std::exp(-2.0)), 1e-14);
}

TEST(FrictionLaw, SitesInEveryLayout) {
  FrictionSites uniform = uniformSites(1.0, 0.5);
  EXPECT_EQ(uniform.slot(3, 2), 0);
  EXPECT_EQ(uniform.slotOfSite(11), 0);
  FrictionSites columns{SiteLayout::PerColumn, 4, {1, 2, 3, 4}, {0.5, 1, 1.5, 2}};
  EXPECT_EQ(columns.slot(3, 2), 2);
  EXPECT_EQ(columns.slotOfSite(3 * 4 + 2), 2);
  EXPECT_EQ(columns.staticAt(columns.slot(1, 3)), 4.0);
  FrictionSites sites{SiteLayout::PerSite, 4, std::vector<double>(16, 1.0), std::vector<double>(16, 0.5)};
  EXPECT_EQ(sites.slot(3, 2), 14);
  EXPECT_EQ(sites.slotOfSite(14), 14);
}

TEST(FrictionLaw, TheRegistryListsAndDispatchesEveryLaw) {
  const auto names = frictionLawNames();
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[0], "coulomb");
  EXPECT_EQ(names[1], "exponential");
  for (const auto& name : names) {
    FrictionLawSettings settings;
    settings.name = name;
    settings.criticalVelocity = 2e-3;
    const double sliding = withFrictionLaw(settings, uniformSites(1.0, 0.6), [](const auto& law) {
      EXPECT_EQ(law.sites.staticStrength[0], 1.0);
      return law.slidingStrength(1.0, 0.6, 2e-3);
    });
    EXPECT_EQ(sliding, name == "coulomb" ? 0.6 : 0.6 + 0.4 * std::exp(-1.0)) << name;
    EXPECT_FALSE(describeFrictionLaw(settings).empty());
  }
  FrictionLawSettings unknown;
  unknown.name = "rate_and_state";
  EXPECT_THROW(withFrictionLaw(unknown, uniformSites(1, 1), [](const auto&) { return 0; }), std::invalid_argument);
}

TEST(FrictionLaw, TheKernelsFrictionOfAStepComesFromTheLaw) {
  // sbm::frictionPerDirection, shared by both kernels: the sliding force of the step divided by
  // the length of its direction (velocity when moving, driving force from rest), zero when stuck.
  FrictionLawSettings settings;
  settings.criticalVelocity = 1.0;
  const auto coulomb = CoulombStickSlip::make(uniformSites(1.0, 0.6), settings);
  const auto exponential = ExponentialVelocityWeakening::make(uniformSites(1.0, 0.6), settings);
  // Moving at speed 2 (speed^2 = 4): Coulomb 0.6 / 2; exponential mu(2) / 2.
  EXPECT_EQ(sbm::frictionPerDirection(coulomb, 1.0, 0.6, 1.0, 4.0, 9.0), 0.6 / 2.0);
  EXPECT_DOUBLE_EQ(sbm::frictionPerDirection(exponential, 1.0, 0.6, 1.0, 4.0, 9.0),
                   (0.6 + 0.4 * std::exp(-2.0)) / 2.0);
  // From rest, driving force 3: along F_mot, at speed zero (exponential: mu_s).
  EXPECT_EQ(sbm::frictionPerDirection(coulomb, 1.0, 0.6, 1.0, 0.0, 9.0), 0.6 / 3.0);
  EXPECT_DOUBLE_EQ(sbm::frictionPerDirection(exponential, 1.0, 0.6, 1.0, 0.0, 9.0), 1.0 / 3.0);
  // Stuck (mobile 0) or no direction at all: no friction.
  EXPECT_EQ(sbm::frictionPerDirection(exponential, 1.0, 0.6, 0.0, 4.0, 9.0), 0.0);
  EXPECT_EQ(sbm::frictionPerDirection(coulomb, 1.0, 0.6, 1.0, 0.0, 0.0), 0.0);
}

TEST(FrictionLaw, TheStickSlipRule) {
  using sbm::StickSlipChange;
  EXPECT_EQ(sbm::stickSlipChange(sbm::Stuck, true), StickSlipChange::None);
  EXPECT_EQ(sbm::stickSlipChange(sbm::Stuck, false), StickSlipChange::StartsToSlip);
  EXPECT_EQ(sbm::stickSlipChange(sbm::Reversed, true), StickSlipChange::Resticks);
  EXPECT_EQ(sbm::stickSlipChange(sbm::Reversed, false), StickSlipChange::SlidesOn);
  EXPECT_EQ(sbm::stickSlipChange(sbm::Slipping, true), StickSlipChange::None);
  EXPECT_EQ(sbm::stickSlipChange(sbm::Slipping, false), StickSlipChange::None);
}
