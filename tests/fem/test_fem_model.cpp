// The assembled model: specialised kernel vs PETSc's generic PetscFE residual, patch test, mass.
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

TEST(FemModel, SpecialisedKernelEqualsGenericResidualOnARandomState) {
  FemParameters q = test::coarse(8, 6, 3);
  const Grading g = test::linear(GradedProperty::YoungsModulus, 0.4);
  PlateModel model(PETSC_COMM_WORLD, q, g);
  DM dmU = model.elastic().displacementDM();
  OwnedVec u, fs, fg;
  ASSERT_EQ(DMCreateGlobalVector(dmU, u.out()), 0);
  ASSERT_EQ(VecDuplicate(u, fs.out()), 0);
  ASSERT_EQ(VecDuplicate(u, fg.out()), 0);
  PetscRandom rnd = nullptr;
  PetscRandomCreate(PETSC_COMM_WORLD, &rnd);
  PetscRandomSetSeed(rnd, 42);
  PetscRandomSeed(rnd);
  VecSetRandom(u, rnd);
  PetscRandomDestroy(&rnd);
  VecScale(u, 1e-7);
  model.elastic().forceSpecialised(u, fs);
  model.elastic().forceGeneric(u, fg);
  PetscReal ng = 0, nd = 0;
  VecNorm(fg, NORM_2, &ng);
  ASSERT_GT(ng, 0.0) << "the generic residual is all zero (field not marked explicit?)";
  VecAXPY(fs, -1.0, fg);
  VecNorm(fs, NORM_2, &nd);
  EXPECT_LT(nd / ng, 1e-12) << "relative difference " << nd / ng;
}

TEST(FemModel, PatchTestUniformStrainIsReproducedExactly) {
  FemParameters q = test::coarse(5, 4, 4);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  DM dmU = model.elastic().displacementDM();
  OwnedVec u, f;
  ASSERT_EQ(DMCreateGlobalVector(dmU, u.out()), 0);
  ASSERT_EQ(VecDuplicate(u, f.out()), 0);
  // u = A x with a general A (uniform strain + rotation).
  const double A[3][3] = {{1e-3, 2e-4, -3e-4}, {5e-4, -7e-4, 1e-4}, {-2e-4, 6e-4, 4e-4}};
  test::setLinearDisplacement(dmU, u, A);
  model.elastic().forceSpecialised(u, f);
  double sigma[3][3];
  test::uniformStress(q.plate.youngsModulus, q.plate.poissonRatio, A, sigma);
  Vec coords = nullptr;
  DMGetCoordinates(dmU, &coords);  // the nodes' positions, read below
  const PetscScalar* x = nullptr;
  VecGetArrayRead(coords, &x);
  PetscInt n = 0;
  VecGetLocalSize(u, &n);
  const double hx = q.plate.length / q.nx, hy = q.plate.length / q.ny, hz = q.plate.thickness / q.nz;
  // Round-off: each nodal force sums ~200 products about 100x larger than the face force.
  const double tol = 1e-10;
  const PetscScalar* ff = nullptr;
  VecGetArrayRead(f, &ff);
  int interior = 0, faceNodes = 0;
  for (PetscInt i = 0; i < n; i += 3) {
    const double px = x[i], py = x[i + 1], pz = x[i + 2];
    auto on = [](double v, double lo, double hi) { return std::fabs(v - lo) < 1e-12 * hi || std::fabs(v - hi) < 1e-12 * hi; };
    const bool bx = on(px, 0, q.plate.length), by = on(py, 0, q.plate.length), bz = on(pz, 0, q.plate.thickness);
    const double scale = std::fabs(sigma[0][0]) * hy * hz;
    if (!bx && !by && !bz) {  // interior node: zero force
      ++interior;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], 0.0, tol * scale);
    } else if (bx && !by && !bz) {  // inside an x face: the traction sigma n times hy hz
      ++faceNodes;
      const double nx = px > 0.5 * q.plate.length ? 1.0 : -1.0;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], -sigma[c][0] * nx * hy * hz, 1e-10 * scale);
    } else if (bz && !bx && !by) {  // inside a z face
      ++faceNodes;
      const double nz = pz > 0.5 * q.plate.thickness ? 1.0 : -1.0;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], -sigma[c][2] * nz * hx * hy, 1e-10 * scale);
    }
  }
  VecRestoreArrayRead(f, &ff);
  VecRestoreArrayRead(coords, &x);
  int counts[2] = {interior, faceNodes}, total[2];
  MPI_Allreduce(counts, total, 2, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(total[0], 4 * 3 * 3);
  EXPECT_GT(total[1], 0);
}

TEST(FemModel, LumpedMassAndFaceAreas) {
  FemParameters q = test::coarse(6, 5, 2);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  EXPECT_NEAR(model.mass().total(), q.plate.density * q.plate.length * q.plate.length * q.plate.thickness, 1e-12 * q.plate.density * q.plate.length * q.plate.length * q.plate.thickness);
  EXPECT_NEAR(model.top().area(), q.plate.length * q.plate.length, 1e-12 * q.plate.length * q.plate.length);
  EXPECT_EQ(model.mesh().globalCells(), 6 * 5 * 2);
  EXPECT_GT(model.stableTimeStep(), 0.0);
  EXPECT_NEAR(model.timeStep(), q.dtSafety * model.stableTimeStep(), 1e-20);
}

// The mirror-basis kernel (4 cells per SIMD lane group) against the dense 24x24 kernel: the same
// force to round-off, for both elements, on a cell count that leaves a short tail, with shared
// nodes (scatter-add order), and the block check refuses a stiffness without the symmetry.
TEST(FemModel, ReflectionBlockKernelEqualsDenseKernel) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const PetscInt cells = 11, nodes = 20;
  std::vector<PetscInt> offsets(8 * cells);
  for (PetscInt c = 0; c < cells; ++c) {
    std::vector<PetscInt> pool(nodes);
    for (PetscInt i = 0; i < nodes; ++i) pool[i] = 3 * i;
    std::shuffle(pool.begin(), pool.end(), rng);
    for (int a = 0; a < 8; ++a) offsets[8 * c + a] = pool[a];
  }
  std::vector<double> modulus(cells), u(3 * nodes);
  for (double& e : modulus) e = 1e7 * (1.0 + 0.5 * uniform(rng));
  for (double& x : u) x = 1e-7 * uniform(rng);
  for (ElementType type : {ElementType::Trilinear, ElementType::IncompatibleModes}) {
    const BoxElement element = makeBoxElement(1e-4, 0.6e-4, 1e-5, 0.3, type);
    std::array<double, 72> blocks{};
    ASSERT_TRUE(reflectionBlocks(element.stiffness.data(), &blocks)) << elementTypeName(type);
    std::vector<double> dense(3 * nodes, 0.0), blocked(3 * nodes, 0.0);
    elasticKernel(cells, offsets.data(), modulus.data(), element.stiffness.data(), u.data(), nullptr, 0.0, dense.data());
    elasticKernelBlocked(cells, offsets.data(), modulus.data(), blocks.data(), u.data(), blocked.data());
    double largest = 0, difference = 0;
    for (std::size_t i = 0; i < dense.size(); ++i) {
      largest = std::max(largest, std::fabs(dense[i]));
      difference = std::max(difference, std::fabs(dense[i] - blocked[i]));
    }
    ASSERT_GT(largest, 0.0);
    EXPECT_LT(difference / largest, 1e-13) << elementTypeName(type);
    std::array<double, 24 * 24> skewed = element.stiffness;  // couples x of node 0 to y of node 1
    skewed[24 * 0 + 4] += 1e-3 * std::fabs(skewed[0]);
    skewed[24 * 4 + 0] += 1e-3 * std::fabs(skewed[0]);
    EXPECT_FALSE(reflectionBlocks(skewed.data(), &blocks)) << elementTypeName(type);
  }
}

// -fem_kernel blocked: the assembled force (ghost exchange included) equals the dense kernel's.
TEST(FemModel, BlockedKernelOptionGivesTheDenseForce) {
  FemParameters q = test::coarse(9, 7, 3);
  const Grading g = test::linear(GradedProperty::YoungsModulus, 0.4);
  q.blockedKernel = false;
  PlateModel dense(PETSC_COMM_WORLD, q, g);
  q.blockedKernel = true;
  PlateModel blocked(PETSC_COMM_WORLD, q, g);
  OwnedVec u, fd, fb;
  ASSERT_EQ(DMCreateGlobalVector(dense.elastic().displacementDM(), u.out()), 0);
  ASSERT_EQ(VecDuplicate(u, fd.out()), 0);
  ASSERT_EQ(VecDuplicate(u, fb.out()), 0);
  PetscRandom rnd = nullptr;
  PetscRandomCreate(PETSC_COMM_WORLD, &rnd);
  PetscRandomSetSeed(rnd, 7);
  PetscRandomSeed(rnd);
  VecSetRandom(u, rnd);
  PetscRandomDestroy(&rnd);
  VecScale(u, 1e-7);
  dense.elastic().forceSpecialised(u, fd);
  blocked.elastic().forceSpecialised(u, fb);
  PetscReal nd = 0, diff = 0;
  VecNorm(fd, NORM_INFINITY, &nd);
  ASSERT_GT(nd, 0.0);
  VecAXPY(fb, -1.0, fd);
  VecNorm(fb, NORM_INFINITY, &diff);
  EXPECT_GT(diff, 0.0) << "the option did not switch the kernel (bitwise equal forces)";
  EXPECT_LT(diff / nd, 1e-13);
}
