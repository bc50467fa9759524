// Option records: defaults, user values, derived values, and refusals naming option and range.
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/physics/grading_options.hpp"

#include "../common/scoped_option.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

using namespace gradfric;

namespace {
using gradfric::testing::ScopedOption;
}  // namespace

TEST(Options, DefaultsUserValuesAndTheRecord) {
  ScopedOption set("-t1_alpha", "2.5");
  RunParameters record;
  OptionReader reader(PETSC_COMM_SELF, "t1_", "test", &record);
  EXPECT_EQ(reader.real("alpha", 1.0, "m", "a length"), 2.5);
  EXPECT_EQ(reader.real("beta", 1.5, "s", "a time"), 1.5);
  reader.recordDerived("gamma", 3.0, "1/s", "derived");
  ASSERT_NE(record.find("-t1_alpha"), nullptr);
  EXPECT_EQ(record.find("-t1_alpha")->origin, OptionOrigin::User);
  EXPECT_EQ(record.find("-t1_beta")->origin, OptionOrigin::Default);
  EXPECT_EQ(record.find("-t1_gamma")->origin, OptionOrigin::Derived);
  EXPECT_EQ(record.find("-t1_alpha")->unit, "m");
}

TEST(Options, MalformedAndOutOfRangeValuesNameTheOption) {
  ScopedOption bad("-t2_alpha", "abc");
  OptionReader reader(PETSC_COMM_SELF, "t2_", "test", nullptr);
  try {
    reader.real("alpha", 1.0, "m", "a length");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-t2_alpha = abc"), std::string::npos) << e.what();
  }
  try {
    reader.requirePositive("beta", -1.0, "Pa");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "invalid option -t2_beta = -1: allowed > 0 [Pa]");
  }
  EXPECT_THROW(reader.choice("kind", "x", {"a", "b"}, "a choice"), InputError);
}

TEST(Options, GradingRefusesDeltaOfOneOrMore) {
  for (const char* value : {"1", "-1", "1.5"}) {
    ScopedOption profile("-grading_profile", "linear");
    ScopedOption delta("-grading_delta", value);
    EXPECT_THROW(readGrading(PETSC_COMM_SELF, nullptr), InputError) << value;
  }
  ScopedOption profile("-grading_profile", "parabolic");
  EXPECT_THROW(readGrading(PETSC_COMM_SELF, nullptr), InputError);
}

TEST(Options, UnknownOptionsWithOurPrefixesAreRefused) {
  ScopedOption typo("-t3_dealta", "0.1");
  EXPECT_THROW(checkUnusedOptions(PETSC_COMM_SELF, {"t3_"}), InputError);
}
