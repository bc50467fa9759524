// The FEM sweep's points, layout and refusals (fem/sweep.hpp), and that a point of a sweep is
// the same run as the FEM's own entry point gives for that grading and angle.
#include "fem_test_util.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/sweep.hpp"
#include "gradfric/io/results_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

FemParameters tinyPlate() {
  FemParameters q = test::coarse(6, 6, 2);
  return q;
}

SweepOptions thetaDeltaSweep() {
  SweepOptions o;
  o.lists.theta = {0.0, 90.0};
  o.lists.delta = {0.0, 0.2};
  o.requested = true;
  return o;
}

// The InputError message of f, or "" if it throws none.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FemSweep, PointsLayoutAndPropertiesFollowTheEnsembleConstruction) {
  const FemParameters q = tinyPlate();
  const Grading g = test::linear(GradedProperty::Friction, 0.1);
  RunParameters record;
  const FemSweep s = buildFemSweep(MPI_COMM_WORLD, q, g, thetaDeltaSweep(), false, record);
  ASSERT_EQ(s.points(), 4);
  EXPECT_EQ(s.sweep.axes, (std::vector<std::string>{"theta", "delta"}));
  const double theta[] = {0, 0, 90, 90}, delta[] = {0, 0.2, 0, 0.2};
  const int reference[] = {0, 0, 2, 2};  // the non-graded point of the same angle
  for (int p = 0; p < 4; ++p) {
    EXPECT_EQ(s.pointParameters(p).plate.slidingAngle, theta[p]);
    EXPECT_EQ(s.pointGrading(p).delta, delta[p]);
    EXPECT_EQ(s.sweep.reference[p], reference[p]);
    EXPECT_FALSE(s.pointParameters(p).verbose);
    EXPECT_TRUE(s.pointParameters(p).output.empty());  // a point writes no file of its own
  }
  EXPECT_EQ(s.layout.format, io::kFemSweepFormatName);
  EXPECT_EQ(s.layout.points, 4);
  EXPECT_EQ(s.layout.realisations, 1);
  // The FEM's axes: its bottom cell columns' centres (cell_x), no lattice, no rows without field maps.
  EXPECT_EQ(s.layout.mapSide, 0);
  ASSERT_EQ(s.layout.cellX.size(), 6u);
  EXPECT_DOUBLE_EQ(s.layout.cellX[0], q.plate.length / 12);
  EXPECT_DOUBLE_EQ(s.layout.cellX[5], q.plate.length * 11 / 12);
  EXPECT_TRUE(s.layout.cellY.empty());
  EXPECT_FALSE(s.layout.springBlock());
  EXPECT_FALSE(s.layout.singleRun());
  EXPECT_EQ(s.layout.historyCapacity,
            static_cast<int>(std::floor(q.slideTime / q.measurement.historyInterval)) + 4);
  // Friction graded along x: column 0 of a Delta = 0.2 point at (1 - 0.2) mu_s, E untouched.
  ASSERT_EQ(s.table.muStatic.size(), 24u);
  EXPECT_DOUBLE_EQ(s.table.muStatic[6 * 1 + 0], q.plate.muStatic * 0.8);
  EXPECT_DOUBLE_EQ(s.table.muKinetic[6 * 1 + 5], q.plate.muKinetic * 1.2);
  EXPECT_DOUBLE_EQ(s.table.modulus[6 * 1 + 0], q.plate.youngsModulus);
  EXPECT_DOUBLE_EQ(s.table.muStatic[6 * 0 + 0], q.plate.muStatic);
}

TEST(FemSweep, RefusesWhatCannotRunNamingTheOption) {
  const FemParameters q = tinyPlate();
  const Grading g = test::linear(GradedProperty::Friction, 0.1);
  RunParameters record;
  SweepOptions sigma = thetaDeltaSweep();
  sigma.lists.sigma = {0.0, 0.1};
  EXPECT_NE(refusal([&] { buildFemSweep(MPI_COMM_WORLD, q, g, sigma, false, record); }).find("-ensemble_sigma"),
            std::string::npos);
  SweepOptions ranks = thetaDeltaSweep();
  ranks.ranksPerRun = 3;
  EXPECT_NE(refusal([&] { buildFemSweep(MPI_COMM_WORLD, q, g, ranks, false, record); })
                .find("-fem_sweep_ranks_per_run = 3: allowed a divisor of the number of ranks 1"),
            std::string::npos);
  FemParameters snapshots = q;
  snapshots.snapshotTimes = {0.0};
  EXPECT_NE(refusal([&] { buildFemSweep(MPI_COMM_WORLD, snapshots, g, thetaDeltaSweep(), false, record); })
                .find("-fem_snapshot_times"),
            std::string::npos);
  EXPECT_NE(refusal([&] { buildFemSweep(MPI_COMM_WORLD, q, g, thetaDeltaSweep(), true, record); })
                .find("-fem_compare_sbm"),
            std::string::npos);
  SweepOptions noProfile = thetaDeltaSweep();
  EXPECT_NE(refusal([&] { buildFemSweep(MPI_COMM_WORLD, q, Grading{}, noProfile, false, record); })
                .find("-ensemble_delta"),
            std::string::npos);
}

TEST(FemSweep, EveryPointIsTheFemRunOfItsGradingAndAngle) {
  FemParameters q = tinyPlate();
  q.output = "test_fem_sweep_" + std::to_string(getpid()) + ".h5";
  q.overwrite = true;
  const Grading g = test::linear(GradedProperty::Friction, 0.1);
  SweepOptions o;
  o.lists.delta = {0.0, 0.3};
  o.requested = true;
  RunParameters record;
  const FemSweep s = buildFemSweep(MPI_COMM_WORLD, q, g, o, false, record);
  runFemSweep(MPI_COMM_WORLD, s, record);
  io::ResultsFile file = io::ResultsFile::openReadOnly(MPI_COMM_WORLD, q.output);
  EXPECT_TRUE(file.complete());
  const std::vector<double> muS = file.readRealisationReal("mu_s");
  const std::vector<double> relative = file.readStatistic("mu_s_relative");
  file.close();
  std::remove(q.output.c_str());
  ASSERT_EQ(muS.size(), 2u);
  for (int p = 0; p < 2; ++p) {  // the same numbers as the FEM's entry point, bit for bit
    PlateModel model(MPI_COMM_WORLD, s.pointParameters(p), s.pointGrading(p));
    const FemRunResult direct = runPlateExperiment(model);
    EXPECT_EQ(muS[p], direct.friction.muStatic) << "point " << p;
  }
  // A friction gradient lowers mu_s (paper Figure 4): the relative variation is negative.
  EXPECT_EQ(relative[0], 0.0);
  EXPECT_LT(relative[1], -0.05);
}
