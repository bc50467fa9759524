// The parallel results file: created collectively, each task written by one rank alone,
// read back identically by every rank; a reopened file gives back its layout, sweep and scene;
// only tasks whose done flag is set count as finished.
#include "gradfric/io/results_file.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace gradfric::io;

namespace {

MPI_Comm comm() { return PETSC_COMM_WORLD; }

std::string tempPath(const char* name) {
  // One path for all ranks: rank 0 chooses it.
  char buffer[256] = "";
  int rank = 0;
  MPI_Comm_rank(comm(), &rank);
  if (rank == 0) std::snprintf(buffer, sizeof buffer, "results_file_test_%s_%d.h5", name, static_cast<int>(getpid()));
  MPI_Bcast(buffer, sizeof buffer, MPI_CHAR, 0, comm());
  return buffer;
}

EnsembleLayout smallLayout() {
  EnsembleLayout l;
  l.points = 3;
  l.realisations = 4;
  l.historyCapacity = 5;
  l.mapSide = 2;
  l.firstSlipMap = true;
  l.snapshotTimes = {1e-5, 2e-5};
  l.statistics = {{"mu_s_mean", "1", "mean of mu_s", false, {{"interval", "none"}}},
                  {"finished", "1", "realisations finished", true, {}}};
  return l;
}

SweepTable smallSweep() {
  SweepTable s;
  s.axes = {"delta"};
  s.delta = {-0.1, 0.0, 0.25};
  s.theta = {0, 0, 0};
  s.sigma = {0.028, 0.028, 0.028};
  s.sigmaKinetic = s.sigma;
  s.property = {"friction", "friction", "friction"};
  s.profile = {"linear", "linear", "linear"};
  s.referencePoint = {1, 1, 1};
  return s;
}

TaskOutput taskOf(int p, int r, int rank) {
  TaskOutput t;
  t.point = p;
  t.realisation = r;
  t.friction.muStatic = 1.0 + 0.01 * p + 0.001 * r;
  t.friction.muKinetic = 0.6 + 0.01 * p;
  t.friction.peakTime = 1e-4 * (p + 1);
  t.endTime = 3e-4;
  t.friction.peakConfirmed = (r % 2) == 0;
  t.steps = 1000 + p * 10 + r;
  t.redrawnBlocks = r;
  t.friction.time = {0.0, 1e-5, 2e-5};
  t.friction.mu = {0.0, 0.5 + p, 0.9 + r};
  t.firstSlipTime = {1.0 * p, 2.0, 3.0, 4.0 * r};
  t.snapshotTime = {1e-5};  // only the first snapshot was reached
  t.snapshots = {{0.1, 0.2, 0.3, 0.4 + p}};
  t.wallSeconds = 0.5;
  t.rank = rank;
  return t;
}

}  // namespace

TEST(ResultsFile, EachRankWritesItsTasksAndEveryRankReadsThemBack) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm(), &rank);
  MPI_Comm_size(comm(), &size);
  const std::string path = tempPath("write");
  const std::vector<Attribute> scene = {{"sbm_N", "20", "1", "set"}, {"grading_profile", "linear", "", "set"},
                                        {"ensemble_note", "", "", "default"}};
  {
    ResultsFile f = ResultsFile::create(comm(), path, smallLayout(), smallSweep(), scene);
    // Task t = p * R + r goes to rank t % size; task (2, 3) is left unfinished.
    for (int p = 0; p < 3; ++p)
      for (int r = 0; r < 4; ++r) {
        if (p == 2 && r == 3) continue;
        if ((p * 4 + r) % size == rank) f.writeTask(taskOf(p, r, rank));
      }
    f.flush();
    MPI_Barrier(comm());
    EXPECT_FALSE(f.complete());
    const auto done = f.finishedTasks();
    ASSERT_EQ(done.size(), 12u);
    for (int i = 0; i < 12; ++i) EXPECT_EQ(done[i], i == 11 ? 0 : 1) << i;
    const auto muS = f.readRealisationReal("mu_s");
    EXPECT_DOUBLE_EQ(muS[2 * 4 + 1], 1.0 + 0.02 + 0.001);
    EXPECT_TRUE(std::isnan(muS[11]));
    f.writeStatistics({{"mu_s_mean", {1.0, 2.0, 3.0}}}, {{"finished", {4, 4, 3}}});
    f.setRunAttributes({{"ranks", std::to_string(size), "", ""}});
    f.markComplete();
    f.close();
  }
  {
    ResultsFile f = ResultsFile::open(comm(), path);
    EXPECT_TRUE(f.complete());
    const auto& l = f.layout();
    EXPECT_EQ(l.points, 3);
    EXPECT_EQ(l.realisations, 4);
    EXPECT_EQ(l.historyCapacity, 5);
    EXPECT_EQ(l.mapSide, 2);
    EXPECT_TRUE(l.firstSlipMap);
    ASSERT_EQ(l.snapshotTimes.size(), 2u);
    EXPECT_DOUBLE_EQ(l.snapshotTimes[1], 2e-5);
    ASSERT_EQ(l.statistics.size(), 2u);  // read back in name order, with type, units and description
    EXPECT_EQ(l.statistics[0].name, "finished");
    EXPECT_TRUE(l.statistics[0].integer);
    EXPECT_EQ(l.statistics[1].name, "mu_s_mean");
    EXPECT_FALSE(l.statistics[1].integer);
    EXPECT_EQ(l.statistics[1].description, "mean of mu_s");
    EXPECT_EQ(l.statistics[1].units, "1");
    const auto& s = f.sweep();
    EXPECT_EQ(s.axes, std::vector<std::string>{"delta"});
    EXPECT_EQ(s.delta, smallSweep().delta);
    EXPECT_EQ(s.property, smallSweep().property);
    EXPECT_EQ(s.referencePoint, smallSweep().referencePoint);
    const auto attributes = f.sceneAttributes();
    ASSERT_EQ(attributes.size(), 3u);
    for (const auto& expected : scene) {
      bool found = false;
      for (const auto& a : attributes)
        if (a.name == expected.name) {
          found = true;
          EXPECT_EQ(a.value, expected.value) << a.name;
          EXPECT_EQ(a.unit, expected.unit) << a.name;
          EXPECT_EQ(a.origin, expected.origin) << a.name;
        }
      EXPECT_TRUE(found) << expected.name;
    }
    const auto confirmed = f.readPeakConfirmed();
    EXPECT_EQ(confirmed[1 * 4 + 2], 1);
    EXPECT_EQ(confirmed[1 * 4 + 3], 0);
    EXPECT_EQ(f.readStatistic("mu_s_mean"), (std::vector<double>{1.0, 2.0, 3.0}));
    f.close();
  }
  // Histories, maps and snapshots land in the slab of their task, padded with NaN.
  if (rank == 0) {
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    auto readAll = [&](const char* name, size_t n) {
      std::vector<double> v(n);
      hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
      EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
      H5Dclose(d);
      return v;
    };
    const auto mu = readAll("history/mu", 12 * 5);
    const size_t at = (1 * 4 + 2) * 5;  // task (1, 2)
    EXPECT_DOUBLE_EQ(mu[at + 1], 1.5);
    EXPECT_DOUBLE_EQ(mu[at + 2], 2.9);
    EXPECT_TRUE(std::isnan(mu[at + 3]));
    const auto slip = readAll("maps/first_slip_time", 12 * 4);
    EXPECT_DOUBLE_EQ(slip[(2 * 4 + 1) * 4 + 0], 2.0);
    EXPECT_DOUBLE_EQ(slip[(2 * 4 + 1) * 4 + 3], 4.0);
    EXPECT_TRUE(std::isnan(slip[11 * 4]));  // the unfinished task keeps the fill value
    const auto stress = readAll("maps/sigma_x_over_p", 12 * 2 * 4);
    EXPECT_DOUBLE_EQ(stress[(0 * 4 + 1) * 8 + 3], 0.4);
    EXPECT_TRUE(std::isnan(stress[(0 * 4 + 1) * 8 + 4]));  // second snapshot never reached
    H5Fclose(file);
    std::remove(path.c_str());
  }
  MPI_Barrier(comm());
}

TEST(ResultsFile, HistoryLongerThanTheCapacityIsRefused) {
  const std::string path = tempPath("capacity");
  int rank = 0;
  MPI_Comm_rank(comm(), &rank);
  ResultsFile f = ResultsFile::create(comm(), path, smallLayout(), smallSweep(), {});
  if (rank == 0) {
    TaskOutput t = taskOf(0, 0, 0);
    t.friction.time.assign(6, 0.0);
    t.friction.mu.assign(6, 0.0);
    EXPECT_THROW(f.writeTask(t), Hdf5Error);
    t = taskOf(5, 0, 0);
    EXPECT_THROW(f.writeTask(t), Hdf5Error);
  }
  f.close();
  if (rank == 0) std::remove(path.c_str());
  MPI_Barrier(comm());
}

TEST(ResultsFile, OtherFilesAreRefused) {
  const std::string path = tempPath("foreign");
  int rank = 0;
  MPI_Comm_rank(comm(), &rank);
  if (rank == 0) {
    hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, 5);
    hid_t a = H5Acreate2(file, "format", type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, type, "other");
    H5Aclose(a);
    H5Tclose(type);
    H5Sclose(space);
    H5Fclose(file);
  }
  MPI_Barrier(comm());
  EXPECT_TRUE(isHdf5File(path));
  EXPECT_FALSE(isHdf5File(path + ".missing"));
  EXPECT_THROW(ResultsFile::open(comm(), path), Hdf5Error);
  MPI_Barrier(comm());
  if (rank == 0) std::remove(path.c_str());
}
