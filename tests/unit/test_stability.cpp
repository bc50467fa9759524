// The shared stability layer: the time-step policy and the monitor's checks.
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace gradfric;

TEST(Stability, TimeStepPolicyRefusesAboveTheLimitNamingTheOption) {
  const TimeStepPolicy policy{"-sbm_dt", "the RK4 stability limit of this lattice", 1e-6, true};
  EXPECT_EQ(policy.choose(std::nullopt, 2.5e-7), 2.5e-7);
  EXPECT_EQ(policy.choose(1e-6, 2.5e-7), 1e-6);  // at the limit: accepted
  try {
    policy.choose(1.5e-6, 2.5e-7);
    FAIL() << "a step above the limit was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.option(), "-sbm_dt");
    EXPECT_NE(std::string(e.what()).find("<= 1e-06 s, the RK4 stability limit"), std::string::npos) << e.what();
  }
  EXPECT_THROW(policy.choose(0.0, 2.5e-7), InputError);
  EXPECT_THROW(policy.choose(std::numeric_limits<double>::infinity(), 2.5e-7), InputError);
  const TimeStepPolicy testing{"-fem_dt", "the stable step", 1e-6, false};
  EXPECT_EQ(testing.choose(3e-6, 1e-7), 3e-6);  // -fem_dt_check false: accepted
}

TEST(Stability, EnergyBoundHoldsBelowTheWorkAndNamesTheExcess) {
  const EnergyBound bound{1.001, 0.0};
  EXPECT_TRUE(bound.violation(1.0, 1.0, "the work done by the slider").empty());
  EXPECT_TRUE(bound.violation(1.0009, 1.0, "the work done by the slider").empty());
  const std::string excess = bound.violation(1.002, 1.0, "the work done by the slider");
  EXPECT_NE(excess.find("exceeds"), std::string::npos) << excess;
  EXPECT_NE(excess.find("the work done by the slider"), std::string::npos) << excess;
  EXPECT_FALSE(bound.violation(std::nan(""), 1.0, "w").empty());
  // A reference energy covers the start of a run, when no work has been done yet.
  const EnergyBound withReference{10.0, 1e-9};
  EXPECT_TRUE(withReference.violation(5e-9, 0.0, "w").empty());
  EXPECT_FALSE(withReference.violation(2e-8, 0.0, "w").empty());
}

TEST(Stability, FrictionCheckAndTheExceptionMessage) {
  EXPECT_TRUE(frictionViolation(0.9, 2.0).empty());
  EXPECT_FALSE(frictionViolation(2.1, 2.0).empty());
  EXPECT_FALSE(frictionViolation(std::numeric_limits<double>::infinity(), 2.0).empty());
  const NumericalInstability e("the spring-block", "mu(t) is not finite", 1.5e-4, 1234, "dt too large");
  EXPECT_EQ(e.step(), 1234);
  EXPECT_DOUBLE_EQ(e.time(), 1.5e-4);
  const std::string m = e.what();
  EXPECT_NE(m.find("unstable at t = 0.00015 s (step 1234): mu(t) is not finite. Likely cause: dt too large"),
            std::string::npos)
      << m;
}
