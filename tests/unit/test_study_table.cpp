// The studies' tables read at run time and the bar they give a run (include/gradfric/core/
// study_table.hpp): a run gets the verdict of the ladder holding its scene and mesh, judged alone.
#include "gradfric/core/study_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace {

using namespace gradfric::study;

const std::string kTable =
    "# observable\tmesh\tvalue\tstd_error\tsamples\tscene\n"
    "mu_s\t50x50x5\t0.950239\t0\t0\t-\n"
    "mu_s\t100x100x10\t0.937429\t0\t0\t-\n"
    "mu_s\t200x200x20\t0.933455\t0\t0\t-\n"
    "mu_s\t100x100x5\t0.936322\t0\t0\t-\n"  // another shape: not in the ladder refined in every direction
    "mu_s\t50x50x5\t0.80\t0\t0\tgrading_delta=0.2,grading_profile=linear,grading_property=friction\n"
    "mu_s\t100x100x10\t0.79\t0\t0\tgrading_profile=linear,grading_property=friction,grading_delta=2e-1\n";

TEST(StudyTable, ARunGetsTheVerdictOfTheLadderOfItsSceneAndShape) {
  const auto rows = parseStudyTable(kTable, "test table");
  ASSERT_EQ(rows.size(), 6u);
  const StudyBar bar = studyBar(rows, "mu_s", {}, {100, 100, 10});
  ASSERT_TRUE(bar.measured) << bar.why;
  ASSERT_EQ(bar.ladder.size(), 3u);
  EXPECT_EQ(bar.verdict.member, 1);
  EXPECT_NEAR(bar.verdict.order, 1.689, 1e-3);  // log2(0.012810 / 0.003974)
  EXPECT_NEAR(bar.verdict.extrapolated, 0.933455 - 0.003974 / (std::pow(2.0, bar.verdict.order) - 1), 1e-9);
  EXPECT_NEAR(bar.verdict.uncertainty, 1.25 * (0.937429 - bar.verdict.extrapolated), 1e-9);
  EXPECT_EQ(ladderText(bar), "50x50x5:0.950239 100x100x10:0.937429 200x200x20:0.933455");
}

TEST(StudyTable, WhatTheStudyDidNotRunIsNotMeasuredWithTheReason) {
  const auto rows = parseStudyTable(kTable, "test table");
  const StudyBar paper = studyBar(rows, "mu_s", {}, {100, 100, 5});
  EXPECT_FALSE(paper.measured);
  EXPECT_TRUE(paper.judged);
  EXPECT_NE(paper.why.find("holds 1 mesh(es)"), std::string::npos) << paper.why;
  const StudyBar shape = studyBar(rows, "mu_s", {}, {6, 6, 2});
  EXPECT_FALSE(shape.judged);
  EXPECT_NE(shape.why.find("no mesh of the shape of 6x6x2"), std::string::npos) << shape.why;
  const StudyBar graded = studyBar(rows, "mu_s", parseSceneKey("grading_delta=0.2,grading_profile=linear,grading_property=friction"),
                                   {50, 50, 5});
  EXPECT_FALSE(graded.measured);
  EXPECT_EQ(graded.ladder.size(), 2u) << "0.2 and 2e-1 are one value";
  // A setting the study never varied (a term, a law parameter) puts the run outside it.
  const StudyBar gravity = studyBar(rows, "mu_s", parseSceneKey("fem_gravity=9.81"), {100, 100, 10});
  EXPECT_FALSE(gravity.measured);
  EXPECT_NE(gravity.why.find("fem_gravity=9.81"), std::string::npos) << gravity.why;
  EXPECT_NE(gravity.why.find("nearest studied scene is -"), std::string::npos) << gravity.why;
  EXPECT_FALSE(studyBar(rows, "mu_s", parseSceneKey("friction_v_c=2e-4"), {100, 100, 10}).measured);
  EXPECT_FALSE(studyBar(rows, "mu_s", {}, {400, 400, 40}).measured) << "a mesh outside the ladder";
  EXPECT_FALSE(studyBar(rows, "mu_k", {}, {100, 100, 10}).measured) << "another observable";
}

// A variation's ladder: mu_s,h = 0.8 (1 + 0.3 h^2) graded and 1 + 0.1 h^2 without the grading, so
// v_h = mu_s,h / mu_s0,h - 1 tends to -0.2 at second order. Its bar is the procedure's on the
// ratios, and it holds the exact limit; a mesh the non-graded plate lacks is left out.
TEST(StudyTable, AVariationIsJudgedOnTheLadderOfItsRatio) {
  std::string table;
  const auto row = [&](int n, double value, const std::string& scene) {
    char line[160];
    std::snprintf(line, sizeof line, "mu_s\t%dx%dx%d\t%.12f\t0\t0\t%s\n", n, n, n / 10, value, scene.c_str());
    table += line;
  };
  const std::string graded = "grading_delta=0.2,grading_profile=linear,grading_property=friction";
  for (const int n : {40, 80, 160, 320}) {
    const double h = 10.0 / n;
    row(n, 0.8 * (1 + 0.3 * h * h), graded);
    if (n != 320) row(n, 1 + 0.1 * h * h, "-");
  }
  const auto rows = parseStudyTable(table, "test table");
  const SceneKey scene = parseSceneKey(graded);
  const StudyBar bar = variationBar(rows, "mu_s", scene, {}, {80, 80, 8});
  ASSERT_TRUE(bar.measured) << bar.why;
  ASSERT_EQ(bar.ladder.size(), 3u);  // 320 has no non-graded row
  std::vector<StudyRow> ratios;
  for (const StudyRow* r : bar.ladder) ratios.push_back(*r);
  for (const StudyRow& r : ratios) {
    const double h = 10.0 / r.mesh[0];
    EXPECT_NEAR(r.value, 0.8 * (1 + 0.3 * h * h) / (1 + 0.1 * h * h) - 1, 1e-11);
  }
  EXPECT_EQ(bar.verdict.convergence, gradfric::verification::Convergence::Monotone);
  EXPECT_NEAR(bar.verdict.value, ratios[1].value, 1e-15);
  EXPECT_LE(std::fabs(bar.verdict.value - (-0.2)), bar.verdict.uncertainty);
  // The same procedure as a mu_s ladder of those values: the bar is the ratio's, nothing added.
  const StudyBar direct = studyBar(ratios, "mu_s", scene, {80, 80, 8});
  EXPECT_EQ(direct.verdict.uncertainty, bar.verdict.uncertainty);
  // A copy keeps its ladder (the derived rows are shared), and a stochastic row is refused.
  const StudyBar copy = bar;
  EXPECT_EQ(copy.ladder[0]->value, ratios[0].value);
  auto noisy = rows;
  noisy[0].stdError = 1e-3;
  const StudyBar refused = variationBar(noisy, "mu_s", scene, {}, {80, 80, 8});
  EXPECT_FALSE(refused.measured);
  EXPECT_NE(refused.why.find("ensembles"), std::string::npos) << refused.why;
  // Without the non-graded plate's rows: not measured, said so.
  const StudyBar alone = variationBar(rows, "mu_s", scene, parseSceneKey("plate_E=2e7"), {80, 80, 8});
  EXPECT_FALSE(alone.measured);
  EXPECT_NE(alone.why.find("plate without the grading"), std::string::npos) << alone.why;
}

TEST(StudyTable, ARowThatDoesNotReadIsAnErrorNamingItsLine) {
  for (const char* bad : {"mu_s\t50x50\t0.9\t0\t0\n", "mu_s\t50x50x5\t0.9\t0\t0\tgrading_delta\n",
                          "mu_s\t50xx5\t0.9\t0\t0\t-\n", "mu_s\t50x50x5\t0.9\t1e-3\t1\t-\n", "mu_s\t50x50x5\t0.9\t0\t0\t-\textra\n",
                          "mu_s\t200x200x20\t0.93\t0\t0\t-\n" /* a second result of one mesh */}) {
    try {
      parseStudyTable(kTable + bad, "test table");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("test table, line 8"), std::string::npos) << e.what();
    }
  }
}

// The tables are read at run time: a new row changes the bar with no rebuild. Through the
// process's one reader (studyTable), from $GRADFRIC_STUDY_DIR.
TEST(StudyTable, ATableIsReadAtRunTimeSoANewRowNeedsNoRebuild) {
  char dir[] = "/tmp/gradfric_study_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  setenv("GRADFRIC_STUDY_DIR", dir, 1);
  std::ofstream(std::string(dir) + "/before.tsv") << kTable;
  EXPECT_FALSE(studyBar("before.tsv", "mu_s", {}, {50, 50, 5}).ladder.empty());
  EXPECT_FALSE(studyBar("before.tsv", "mu_s", {}, {100, 100, 5}).measured);
  std::ofstream(std::string(dir) + "/after.tsv") << kTable << "mu_s\t200x200x10\t0.933\t0\t0\t-\nmu_s\t400x400x20\t0.932\t0\t0\t-\n";
  EXPECT_NE(studyTablePath("after.tsv").find(dir), std::string::npos);
  EXPECT_TRUE(studyBar("after.tsv", "mu_s", {}, {100, 100, 5}).measured) << "two rows made its ladder";
  const StudyBar missing = studyBar("no_such_table.tsv", "mu_s", {}, {100, 100, 10});
  EXPECT_FALSE(missing.measured);
  EXPECT_NE(missing.why.find("no_such_table.tsv was not found"), std::string::npos) << missing.why;
  unsetenv("GRADFRIC_STUDY_DIR");
  // The shipped tables are found from the build tree, and every row of them reads.
  EXPECT_FALSE(studyTable("fem_study.tsv").empty());
  EXPECT_FALSE(studyTable("sbm_study.tsv").empty());
}

}  // namespace
