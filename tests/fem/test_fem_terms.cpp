// The registry of the optional FEM terms (term_registry.hpp, src/fem/terms/terms.def):
//  - every registered term is complete (name, reader, wanted, build) and its name unique;
//  - the -fem_ reader reads every term's options: each option a term reads alone, among them
//    -fem_<name>, is in the reader's record (the record -help lists and the results file's /scene
//    holds; test fem_term_help_<name> runs the driver's -help);
//  - PlateModel builds a term exactly when it is wanted: gravity off (0) and on (a tiny g, 9.81,
//    through the option), before the contact; its dead load counted only when on.
#include "gradfric/fem/parameter_options.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/term_registry.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <string>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

int layerIndex(const PlateModel& model, const char* name) {
  const auto& layers = model.layers();
  for (std::size_t i = 0; i < layers.size(); ++i)
    if (std::strcmp(layers[i]->name(), name) == 0) return static_cast<int>(i);
  return -1;
}

const FemTerm& registered(const char* name) {
  const auto& terms = femTerms();
  const auto found =
      std::find_if(terms.begin(), terms.end(), [&](const FemTerm& t) { return std::strcmp(t.name, name) == 0; });
  if (found == terms.end()) throw std::runtime_error(std::string("no term ") + name + " in terms.def");
  return *found;
}

}  // namespace

TEST(FemTerms, EveryTermIsCompleteAndNamedOnce) {
  ASSERT_FALSE(femTerms().empty());
  std::set<std::string> names;
  for (const FemTerm& term : femTerms()) {
    EXPECT_GT(std::strlen(term.name), 0u);
    EXPECT_TRUE(names.insert(term.name).second) << term.name << " registered twice";
    EXPECT_NE(term.readOptions, nullptr) << term.name;
    EXPECT_NE(term.wanted, nullptr) << term.name;
    EXPECT_NE(term.build, nullptr) << term.name;
  }
  EXPECT_EQ(names.count("gravity"), 1u);
}

TEST(FemTerms, TheReaderReadsEveryTermsOptions) {
  RunParameters all;
  readFemParameters(PETSC_COMM_WORLD, &all, Plate{});
  for (const FemTerm& term : femTerms()) {
    RunParameters alone;
    OptionReader o(PETSC_COMM_WORLD, "fem_", "one term", &alone);
    FemParameters q;
    term.readOptions(o, q);
    EXPECT_NE(alone.find(std::string("-fem_") + term.name), nullptr) << term.name << " has no option -fem_" << term.name;
    for (const ResolvedOption& option : alone.all()) {
      const ResolvedOption* read = all.find(option.name);
      ASSERT_NE(read, nullptr) << option.name << " (term " << term.name << ") is not read by readFemParameters";
      EXPECT_EQ(read->value, option.value);
      EXPECT_EQ(read->unit, option.unit);
      EXPECT_EQ(read->help, option.help);
    }
  }
}

TEST(FemTerms, GravityIsBuiltExactlyWhenItsOptionIsPositive) {
  const FemTerm& gravity = registered("gravity");
  for (double g : {0.0, 1e-30, 9.81}) {
    FemParameters q = test::coarse(4, 4, 2);
    if (g != 0.0) q.terms.set("gravity", g);
    const PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    const int at = layerIndex(model, "gravity");
    EXPECT_EQ(gravity.wanted(q), g > 0) << "g " << g;
    EXPECT_EQ(at >= 0, g > 0) << "g " << g;
    if (at >= 0) {
      EXPECT_LT(at, layerIndex(model, "contact")) << "the kinematic contact needs every other force";
    }
    const DeadLoads dead = deadLoadsOf(q);
    EXPECT_EQ(dead.pressure, q.plate.density * g * q.plate.thickness) << "g " << g;
    EXPECT_EQ(dead.symbols, g > 0 ? " + rho g H" : "");
  }
}

TEST(FemTerms, GravityThroughItsOption) {
  ASSERT_EQ(PetscOptionsSetValue(nullptr, "-fem_gravity", "1e4"), 0);
  RunParameters record;
  FemParameters q = readFemParameters(PETSC_COMM_WORLD, &record, Plate{});
  PetscOptionsClearValue(nullptr, "-fem_gravity");
  EXPECT_EQ(q.terms.get("gravity", 0.0), 1e4);
  const ResolvedOption* option = record.find("-fem_gravity");
  ASSERT_NE(option, nullptr);
  EXPECT_EQ(option->value, "10000");
  EXPECT_EQ(option->origin, OptionOrigin::User);
  q.nx = q.ny = 4;
  q.nz = 2;
  q.verbose = false;
  const PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  EXPECT_GE(layerIndex(model, "gravity"), 0);
}
