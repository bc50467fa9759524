// A run gets a study's bar only if it is the study's run (include/gradfric/study/scene_key.hpp):
// its scene key is every option set to a value other than its default, read by the real readers.
#include "gradfric/fem/scene_options.hpp"
#include "gradfric/fem/sweep.hpp"
#include "gradfric/study/scene_key.hpp"

#include "../common/scoped_option.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

using namespace gradfric;
using gradfric::testing::ScopedOption;

namespace {

// The FEM run of the options set now, and its key and mu_s bar from the shipped study table.
struct FemRunKey {
  RunParameters record;
  fem::FemScene scene;
  study::SceneKey key;
  study::StudyBar bar;
};

FemRunKey femRun() {
  FemRunKey r;
  r.scene = fem::readFemScene(PETSC_COMM_WORLD, &r.record);
  r.key = study::sceneKey(r.record, {"-fem_nx", "-fem_ny", "-fem_nz"});
  r.bar = fem::femStudyBar(r.record, nullptr, r.scene.params, "mu_s");
  return r;
}

TEST(SceneKey, TheDefaultRunIsTheStudysRunAndGetsItsBar) {
  const ScopedOption nx("-fem_nx", "100"), output("-output", "x.h5"), observables("-friction_observables", "mu_s");
  const FemRunKey r = femRun();
  EXPECT_TRUE(r.key.empty()) << study::sceneText(r.key) << ": an option at its default or steering only is not in it";
  EXPECT_TRUE(r.bar.measured) << r.bar.why;
}

TEST(SceneKey, ATermTheStudyNeverRanPutsTheRunOutsideIt) {
  const ScopedOption gravity("-fem_gravity", "9.81");
  const FemRunKey r = femRun();
  ASSERT_EQ(r.key.size(), 1u) << study::sceneText(r.key);
  EXPECT_EQ(r.key[0].first, "fem_gravity");
  EXPECT_FALSE(r.bar.measured);
  EXPECT_NE(r.bar.why.find("fem_gravity=9.81"), std::string::npos) << r.bar.why;
}

TEST(SceneKey, APetscObjectsOptionCountsThoughNoReaderRecordsIt) {
  const ScopedOption ts("-fem_ts_type", "rk");
  const FemRunKey r = femRun();
  EXPECT_EQ(study::sceneText(r.key), "fem_ts_type=rk");
  EXPECT_FALSE(r.bar.measured);
}

TEST(SceneKey, ALawParameterTheStudyNeverVariedPutsTheRunOutsideIt) {
  const ScopedOption vc("-friction_v_c", "2e-4");
  const FemRunKey r = femRun();
  EXPECT_EQ(study::sceneText(r.key), "friction_v_c=0.0002");
  EXPECT_FALSE(r.bar.measured);
}

TEST(SceneKey, AnInactiveGradingHasNoEffectAndASweepPointBringsItsOwn) {
  const ScopedOption profile("-grading_profile", "linear"), property("-grading_property", "friction");
  const FemRunKey flat = femRun();  // Delta 0: the grading does nothing
  EXPECT_TRUE(flat.key.empty()) << study::sceneText(flat.key);
  campaign::SweepPoint point;
  point.profile = "linear", point.property = "friction", point.delta = 0.2;
  EXPECT_EQ(study::sceneText(study::sceneKey(flat.record, {"-fem_nx", "-fem_ny", "-fem_nz"}, &point)),
            "grading_delta=0.2,grading_profile=linear,grading_property=friction");
}

}  // namespace
