#include "gradfric/physics/friction_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;

TEST(FrictionLaw, CoulombHoldsUpToTheStaticThreshold) {
  const CoulombStickSlip law{1.0, 0.6};
  EXPECT_TRUE(law.holds(2.0 * 2.0, 2.0));
  EXPECT_FALSE(law.holds(2.0001 * 2.0001, 2.0));
  EXPECT_DOUBLE_EQ(law.kineticForce(2.0), 1.2);
}

TEST(FrictionLaw, ExponentialWeakeningOfEquationOne) {
  const ExponentialVelocityWeakening law{1.0, 0.6, 1e-4};
  EXPECT_DOUBLE_EQ(law.coefficient(0.0), 1.0);
  EXPECT_NEAR(law.coefficient(1e-4), 0.6 + 0.4 / M_E, 1e-15);
  EXPECT_NEAR(law.coefficient(1.0), 0.6, 1e-12);
  EXPECT_GT(law.coefficient(1e-5), law.coefficient(2e-5));
}
