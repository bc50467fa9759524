// Two ranks: the same mu(t) history as one rank, and the METIS partition's balance and cut.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/partition.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

TEST(FemParallel, OneAndTwoRanksGiveTheSameFrictionHistory) {
  int size = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  ASSERT_EQ(size, 2) << "run with 2 ranks";
  FemParameters q = test::coarse(12, 10, 2);
  const Grading g = test::linear(GradedProperty::Both, 0.2);
  // Two ranks.
  FemRunResult two;
  {
    PlateModel model(PETSC_COMM_WORLD, q, g);
    two = runPlateExperiment(model);
  }
  // One rank (each rank runs the serial model on its own).
  FemRunResult one;
  {
    PlateModel model(PETSC_COMM_SELF, q, g);
    one = runPlateExperiment(model);
  }
  ASSERT_EQ(one.mu.size(), two.mu.size());
  double worst = 0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < one.mu.size(); ++i) {
    const double d = std::fabs(one.mu[i] - two.mu[i]) / std::max(1e-300, std::fabs(one.mu[i]));
    if (d > worst) worst = d, at = i;
  }
  PetscPrintf(PETSC_COMM_WORLD,
              "1 vs 2 ranks: %zu samples, largest relative difference of mu(t) %.3e (t - t0 = %.4e s, mu %.9f vs %.9f); "
              "mu_s %.12f vs %.12f\n",
              one.mu.size(), worst, one.time[at], one.mu[at], two.mu[at], one.friction.muStatic, two.friction.muStatic);
  // Not bitwise: the two runs sum each node's cell forces, and the contact totals, in other orders.
  // The tolerance is the round-off growth of this scene measured with bench_fem_roundoff (cells in
  // 5 shuffled orders, blocked kernel, the default, and dense): largest mu(t) difference between
  // two orders 3.2e-11 (dense 2.8e-11, dense vs blocked 4.0e-11); 1 vs 2 ranks gives 1.8e-11.
  // With the state law (the default since its weakening makes mu_s converge) the weakening
  // amplifies round-off further: on one rank, bench_fem_roundoff on this scene now gives 4.1e-10
  // between cell orders (the old law 1.2e-11), and 1 vs 2 ranks gave 4.3e-10: the same floor.
  // 1e-9 is 2.3 x that: a real difference (a lost ghost contribution, a wrong partition of the
  // contact totals) is many orders larger.
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(one.friction.muStatic, two.friction.muStatic, 1e-10 * one.friction.muStatic);
}

TEST(FemParallel, MetisPartitionIsBalancedAndCutsNoMoreFacesThanSimple) {
  int size = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  ASSERT_EQ(size, 2);
  const PetscInt faces[3] = {30, 30, 3};
  const PetscReal lower[3] = {0, 0, 0}, upper[3] = {5e-3, 5e-3, 5e-5};
  OwnedDM serial;
  ASSERT_EQ(DMPlexCreateBoxMesh(PETSC_COMM_WORLD, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE,
                                serial.out()),
            0);
  const std::vector<PetscInt> metis = partitionCells(serial, "metis");
  const std::vector<PetscInt> simple = partitionCells(serial, "simple");
  const PetscInt cutMetis = countCutFaces(serial, metis);
  const PetscInt cutSimple = countCutFaces(serial, simple);
  if (rank == 0) {
    const PetscInt n = 30 * 30 * 3;
    const auto inPart0 = std::count(metis.begin(), metis.end(), 0);
    const double imbalance = std::fabs(double(inPart0) - 0.5 * n) / (0.5 * n);
    std::printf("METIS: imbalance %.4f, cut faces %d; simple: cut faces %d\n", imbalance, int(cutMetis), int(cutSimple));
    EXPECT_LT(imbalance, 0.05);
    EXPECT_GT(cutMetis, 0);
    EXPECT_LE(cutMetis, cutSimple);
  }
  // The distributed mesh really carries METIS's partition: cells per rank balanced.
  FemParameters q = test::coarse(30, 30, 3);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  PetscInt local = model.mesh().localCells(), most = 0;
  MPI_Allreduce(&local, &most, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD);
  EXPECT_LT(double(most), 1.05 * 0.5 * model.mesh().globalCells());
  EXPECT_EQ(model.mesh().globalCells(), 30 * 30 * 3);
}
