// N ranks: the same history as one rank, bit for bit; and the METIS partition's balance and cut.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/first_slip_map.hpp"
#include "gradfric/fem/partition.hpp"
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

// The number of entries of a and b whose bits differ (sizes must agree).
std::size_t differingEntries(const std::vector<double>& a, const std::vector<double>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(double)) != 0;
  return n;
}

void expectSameBits(const char* what, const std::vector<double>& one, const std::vector<double>& many) {
  ASSERT_EQ(one.size(), many.size()) << what << ": another number of samples";
  EXPECT_EQ(differingEntries(one, many), 0u) << what << ": entries that differ in their bits";
}

}  // namespace

// The whole run, not only mu_s: every step's mu(t), forces and normal force, the energy samples,
// the observer's results, the first-slip map and the step count are the same bits on N ranks as
// on one. Every nodal sum is taken in the global cell order (fem/ordered_assembly.hpp) and every total over ranks is
// exact (core/exact_sum.hpp); before, the sliding phase amplified the last-bit differences of
// rank-partial sums to 6 % in mu(t) after the peak (bench_fem_roundoff shows the same growth from
// a change of the cell order on one rank). The scene slides well past the peak, with the state
// law, a graded plate, and the bulk viscosity and the peak damping on.
namespace {

void expectSameHistoryOnOneAndManyRanks(const FemParameters& q, const Grading& g) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  FemRunResult many;
  FirstSlipMap mapMany;  // gathered on rank 0
  {
    PlateModel model(PETSC_COMM_WORLD, q, g);
    many = runPlateExperiment(model);
    mapMany = gatherFirstSlipMap(model);
  }
  FemRunResult one;  // each rank runs the serial model on its own
  FirstSlipMap mapOne;
  {
    PlateModel model(PETSC_COMM_SELF, q, g);
    one = runPlateExperiment(model);
    mapOne = gatherFirstSlipMap(model);
  }
  PetscPrintf(PETSC_COMM_WORLD, "1 vs %d ranks: %zu steps of sliding, mu_s %.17g vs %.17g, mu_k %.17g vs %.17g\n", size,
              one.mu.size(), one.friction.muStatic, many.friction.muStatic, one.friction.muKinetic,
              many.friction.muKinetic);
  ASSERT_TRUE(std::isfinite(one.friction.muKinetic)) << "the scene must reach the kinetic window";
  EXPECT_EQ(one.steps, many.steps);
  expectSameBits("time", one.time, many.time);
  expectSameBits("mu", one.mu, many.mu);
  expectSameBits("force_x", one.forceX, many.forceX);
  expectSameBits("force_y", one.forceY, many.forceY);
  expectSameBits("normal force", one.normalForce, many.normalForce);
  expectSameBits("energy", one.energy, many.energy);
  expectSameBits("energy put in", one.energyIn, many.energyIn);
  expectSameBits("energy dissipated", one.energyDissipated, many.energyDissipated);
  const std::vector<double> observed1 = {one.friction.muStatic, one.friction.muKinetic, one.friction.peakTime,
                                         one.friction.firstSlipTime, one.peakDampingStart};
  const std::vector<double> observedN = {many.friction.muStatic, many.friction.muKinetic, many.friction.peakTime,
                                         many.friction.firstSlipTime, many.peakDampingStart};
  expectSameBits("mu_s, mu_k, peak time, first slip, damping start", observed1, observedN);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    ASSERT_EQ(mapOne.time.size(), std::size_t(q.nx + 1) * (q.ny + 1));
    expectSameBits("first-slip map", mapOne.time, mapMany.time);
  }
}

}  // namespace

TEST(FemParallel, AnyNumberOfRanksGivesTheSameHistoryBitForBit) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  ASSERT_GE(size, 2) << "run with 2 or more ranks";
  // Three ranks on two cores wait for each other a lot: a smaller plate there (still vertices
  // shared by three ranks).
  FemParameters q = size > 2 ? test::coarse(9, 7, 2) : test::coarse(12, 10, 2);
  q.bulkLinear = 0.06;
  q.bulkQuadratic = 1.2;
  q.energyAudit = true;
  expectSameHistoryOnOneAndManyRanks(q, test::linear(GradedProperty::Both, 0.2));
}

// The same on a mesh graded toward the edges (the kernels take each cell's shape; the cell order
// comes from the mapped axes): the smallest mesh of ratio 4 (12 cells a side: 2 in each edge
// band, 1 in the others).
TEST(FemParallel, GradedMeshGivesTheSameHistoryBitForBit) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  ASSERT_GE(size, 2) << "run with 2 or more ranks";
  FemParameters q = test::coarse(12, 12, 2);
  q.edge.ratio = 4.0;
  q.bulkLinear = 0.06;
  q.bulkQuadratic = 1.2;
  expectSameHistoryOnOneAndManyRanks(q, test::linear(GradedProperty::Both, 0.2));
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
