// Paper Eq. 4 (linear) and Eq. 5 (triangular) band factors.
#include "gradfric/physics/grading.hpp"

#include <gtest/gtest.h>

using namespace gradfric;

TEST(Grading, LinearBandsRunFromOneMinusToOnePlusDelta) {
  Grading g{GradingProfile::Linear, GradedProperty::YoungsModulus, 0.2, 10};
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 0.8);
  EXPECT_DOUBLE_EQ(g.bandFactor(9), 1.2);
  for (int i = 0; i < 10; ++i) EXPECT_NEAR(g.bandFactor(i), 1 + 0.2 * (2.0 * i / 9 - 1), 1e-15);
  double mean = 0;
  for (int i = 0; i < 10; ++i) mean += g.bandFactor(i) / 10;
  EXPECT_NEAR(mean, 1.0, 1e-15);  // the mean property is the reference value
}

TEST(Grading, TriangularPeaksAtTheCentreForPositiveDelta) {
  Grading g{GradingProfile::Triangular, GradedProperty::YoungsModulus, 0.2, 11};
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 0.8);
  EXPECT_DOUBLE_EQ(g.bandFactor(5), 1.2);
  EXPECT_DOUBLE_EQ(g.bandFactor(10), 0.8);
  g.delta = -0.2;
  EXPECT_DOUBLE_EQ(g.bandFactor(5), 0.8);
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 1.2);
}

TEST(Grading, BandsAreEqualSlicesOfThePlate) {
  Grading g{GradingProfile::Linear, GradedProperty::Friction, 0.3, 4};
  EXPECT_EQ(g.bandOf(0.0), 0);
  EXPECT_EQ(g.bandOf(0.2499), 0);
  EXPECT_EQ(g.bandOf(0.25), 1);
  EXPECT_EQ(g.bandOf(0.99), 3);
  EXPECT_EQ(g.bandOf(1.0), 3);  // the right edge belongs to the last band
}

TEST(Grading, PropertySelectionAndNoGrading) {
  Grading g{GradingProfile::Linear, GradedProperty::Friction, 0.3, 4};
  EXPECT_TRUE(g.gradesFriction());
  EXPECT_FALSE(g.gradesModulus());
  EXPECT_DOUBLE_EQ(g.modulusFactor(0.0), 1.0);
  EXPECT_DOUBLE_EQ(g.frictionFactor(0.0), 0.7);
  g.property = GradedProperty::Both;
  EXPECT_TRUE(g.gradesFriction() && g.gradesModulus());
  Grading none;
  EXPECT_FALSE(none.active());
  EXPECT_DOUBLE_EQ(none.frictionFactor(0.1), 1.0);
  Grading zero{GradingProfile::Triangular, GradedProperty::Both, 0.0, 10};
  EXPECT_FALSE(zero.active());  // Delta = 0 is the uniform plate: uniform code paths
}

// One table of profiles: every profile has its row, every name parses back to it, the options'
// allowed values are the table's names, and an unknown name is refused (not read as triangular).
TEST(Grading, EveryProfileIsOneRowOfTheTable) {
  const std::vector<std::string> names = gradingProfileNames();
  ASSERT_EQ(names.size(), std::size(kGradingProfiles));
  EXPECT_EQ(names.front(), "none");
  for (const GradingProfileRow& row : kGradingProfiles) {
    EXPECT_EQ(parseGradingProfile(row.name), row.profile);
    EXPECT_STREQ(toString(row.profile), row.name);
  }
  EXPECT_THROW(parseGradingProfile("parabolic"), std::invalid_argument);
  // The band factor is the row's, at s = -1 .. 1: Eq. 4 and Eq. 5 at the ends and the centre.
  Grading g;
  g.delta = 0.3;
  g.bands = 11;
  g.profile = GradingProfile::Linear;
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 0.7);
  EXPECT_DOUBLE_EQ(g.bandFactor(5), 1.0);
  g.profile = GradingProfile::Triangular;
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 0.7);
  EXPECT_DOUBLE_EQ(g.bandFactor(5), 1.3);
  g.profile = GradingProfile::None;
  EXPECT_DOUBLE_EQ(g.bandFactor(0), 1.0);
}
