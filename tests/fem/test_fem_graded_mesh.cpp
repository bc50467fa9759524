// Meshes graded toward the edges (fem/edge_grading.hpp): the mesh at ratio 1, the fields over the
// graded cells, the patch test, the stable step against the assembled M^-1 K, and the moment
// balance of the contact pressure. The map alone, without PETSc: tests/unit/test_fem_edge_map.cpp.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/contact_resultants.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/fem/verlet_ts.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

constexpr double kL = 5e-3;

FemParameters graded(int nx, int ny, int nz, double ratio, const Plate& plate = Plate{}) {
  FemParameters q = test::coarse(nx, ny, nz, plate);
  q.edge.ratio = ratio;
  return q;
}

}  // namespace

TEST(FemGradedMesh, RatioOneBuildsTheUniformBoxCellOnly) {
  // The mesh built at ratio 1: one cell shape, the uniform box's.
  PlateModel model(PETSC_COMM_WORLD, test::coarse(6, 5, 2), test::noGrading());
  const PlateMesh& mesh = model.mesh();
  ASSERT_EQ(mesh.shapes().size(), 1u);
  EXPECT_EQ(mesh.shapes()[0][0], mesh.size().length / 6);
  EXPECT_EQ(mesh.shapes()[0][1], mesh.size().length / 5);
  EXPECT_EQ(mesh.shapes()[0][2], mesh.size().thickness / 2);
}

TEST(FemGradedMesh, MeanPreservingFieldsAreNormalisedOverTheGradedCellsAreaWeighted) {
  PropertyField step;  // a step off-centre: its plain mean over the graded cells is not its area mean
  step.length = kL;
  step.shape = FieldShape::Step;
  step.delta = 0.4;
  step.position = 0.7e-3;
  step.normalise = true;
  PlateFields fields;
  fields.modulus = std::make_shared<const PropertyField>(step);
  Grading g;
  g.fields = std::make_shared<const PlateFields>(fields);
  const MeshAxis x = makeMeshAxis(EdgeGrading{4.0, kL / 10}, 48, kL), y = makeMeshAxis(EdgeGrading{4.0, kL / 10}, 24, kL);
  const PropertySampler sampler = meshSampler(g, x, y);
  double area = 0, weighted = 0, plain = 0;
  for (int j = 0; j < y.cells(); ++j)
    for (int i = 0; i < x.cells(); ++i) {
      const double a = x.width(i) * y.width(j), f = sampler.modulus(x.unitCentre(i), y.unitCentre(j));
      area += a;
      weighted += a * f;
      plain += f / (x.cells() * y.cells());
    }
  EXPECT_NEAR(weighted / area, 1.0, 1e-12);
  EXPECT_GT(std::fabs(plain - 1.0), 1e-3) << "the test needs cells of unequal weight under the step";
}

TEST(FemGradedMesh, PatchTestUniformStrainGivesExactTractions) {
  const FemParameters q = graded(24, 12, 3, 4.0);
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  ASSERT_GT(model.mesh().shapes().size(), 1u);
  DM dmU = model.elastic().displacementDM();
  OwnedVec u, f;
  ASSERT_EQ(DMCreateGlobalVector(dmU, u.out()), 0);
  ASSERT_EQ(VecDuplicate(u, f.out()), 0);
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
  // A node's share of a face: half of each neighbouring cell's width along both face directions.
  const MeshAxis& ax = model.mesh().axisX();
  const MeshAxis& ay = model.mesh().axisY();
  const MeshAxis az = makeMeshAxis(EdgeGrading{}, q.nz, q.plate.thickness);
  const auto share = [](const MeshAxis& axis, double v) {
    const int k = axis.nearestNode(v);
    return 0.5 * ((k > 0 ? axis.width(k - 1) : 0.0) + (k < axis.cells() ? axis.width(k) : 0.0));
  };
  const double scale = std::fabs(sigma[0][0]) * ax.width(0) * q.plate.thickness / q.nz;
  const PetscScalar* ff = nullptr;
  VecGetArrayRead(f, &ff);
  int counts[3] = {0, 0, 0};  // interior nodes, x-face nodes, z-face nodes
  for (PetscInt i = 0; i < n; i += 3) {
    const double px = x[i], py = x[i + 1], pz = x[i + 2];
    auto on = [](double v, double hi) { return std::fabs(v) < 1e-12 * hi || std::fabs(v - hi) < 1e-12 * hi; };
    const bool bx = on(px, q.plate.length), by = on(py, q.plate.length), bz = on(pz, q.plate.thickness);
    if (!bx && !by && !bz) {
      ++counts[0];
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], 0.0, 1e-10 * scale) << "interior node at " << px << ", " << py;
    } else if (bx && !by && !bz) {
      ++counts[1];
      const double normal = px > 0.5 * q.plate.length ? 1.0 : -1.0, area = share(ay, py) * share(az, pz);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], -sigma[c][0] * normal * area, 1e-10 * scale);
    } else if (bz && !bx && !by) {
      ++counts[2];
      const double normal = pz > 0.5 * q.plate.thickness ? 1.0 : -1.0, area = share(ax, px) * share(ay, py);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(ff[i + c], -sigma[c][2] * normal * area, 1e-10 * scale);
    }
  }
  VecRestoreArrayRead(f, &ff);
  VecRestoreArrayRead(coords, &x);
  int total[3];
  MPI_Allreduce(counts, total, 3, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(total[0], 23 * 11 * 2);
  EXPECT_EQ(total[1], 2 * 11 * 2);
  EXPECT_EQ(total[2], 2 * 23 * 11);
  // The mass and the bottom area of the graded cells add up to the plate's.
  const double volume = q.plate.length * q.plate.length * q.plate.thickness;
  EXPECT_NEAR(model.mass().total(), q.plate.density * volume, 1e-12 * q.plate.density * volume);
}

namespace {

// The largest eigenvalue of the assembled M^-1 K (Rayleigh quotient of a power iteration from a
// random start; from below).
double largestFrequencySquared(PlateModel& model, int iterations) {
  DM dmU = model.elastic().displacementDM();
  OwnedVec v, kv;
  DMCreateGlobalVector(dmU, v.out());
  VecDuplicate(v, kv.out());
  PetscInt n = 0;
  VecGetLocalSize(v, &n);
  const std::vector<double>& inverse = model.mass().inversePerBlock();
  const std::vector<double>& mass = model.mass().perBlock();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  PetscScalar* a = nullptr;
  VecGetArray(v, &a);
  for (PetscInt i = 0; i < n; ++i) a[i] = uniform(random);
  VecRestoreArray(v, &a);
  double rayleigh = 0;
  for (int it = 0; it < iterations; ++it) {
    model.elastic().forceSpecialised(v, kv);  // -K v
    const PetscScalar* f = nullptr;
    PetscScalar* w = nullptr;
    VecGetArrayRead(kv, &f);
    VecGetArray(v, &w);
    double local[3] = {0, 0, 0};  // v.Kv, v.Mv, |M^-1 K v|^2
    for (PetscInt i = 0; i < n; ++i) {
      local[0] += -f[i] * w[i];
      local[1] += mass[i / 3] * w[i] * w[i];
    }
    for (PetscInt i = 0; i < n; ++i) {
      w[i] = -f[i] * inverse[i / 3];
      local[2] += w[i] * w[i];
    }
    double sum[3];
    MPI_Allreduce(local, sum, 3, MPI_DOUBLE, MPI_SUM, model.comm());
    rayleigh = sum[0] / sum[1];
    for (PetscInt i = 0; i < n; ++i) w[i] /= std::sqrt(sum[2]);
    VecRestoreArray(v, &w);
    VecRestoreArrayRead(kv, &f);
  }
  return rayleigh;
}

}  // namespace

TEST(FemGradedMesh, StableStepIsWithinTheAssembledOneAndARunThereStaysBounded) {
  // Ratio 8 on a thick layer: the small edge cells, not the thickness, set the step.
  Plate unloaded;
  unloaded.pressure = 0;
  FemParameters q = graded(28, 28, 1, 8.0, unloaded);
  q.contact = false;
  q.settleDamping = 0;
  q.peakDamping = 0;
  q.dtSafety = 1.0;
  PlateModel model(PETSC_COMM_WORLD, q, test::linear(GradedProperty::YoungsModulus, 0.3));
  const double computed = model.stableTimeStep();
  const double truth = 2.0 / std::sqrt(largestFrequencySquared(model, 3000));
  FemParameters uniform = q;
  uniform.edge = EdgeGrading{};
  const double interiorOnly = stableTimeStep(uniform, test::linear(GradedProperty::YoungsModulus, 0.3));
  PetscPrintf(PETSC_COMM_WORLD, "stable step: computed %.4e s, assembled M^-1 K %.4e s (ratio %.3f); uniform mesh %.4e s\n",
              computed, truth, computed / truth, interiorOnly);
  EXPECT_LE(computed, truth * (1 + 1e-9));
  EXPECT_GT(computed, 0.6 * truth);
  EXPECT_LT(computed, 0.7 * interiorOnly) << "the edge cells must shorten the step";

  // Verlet at the computed step from random velocities (every mode excited): bounded energy.
  OwnedVec X(model.createState());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniformVelocity(-1e-3, 1e-3);
  test::setState(model, X, [&](const double*, double* u, double* v) {
    for (int d = 0; d < 3; ++d) u[d] = 0, v[d] = uniformVelocity(random);
  });
  OwnedTS ts(createPlateTS(model, X));
  Vec s = nullptr;
  TSGetSolution(ts, &s);
  const double e0 = model.kineticEnergy(s) + model.elasticEnergy(s);
  double largest = e0;
  for (int step = 0; step < 2000; ++step) {
    ASSERT_EQ(TSStep(ts), 0);
    TSGetSolution(ts, &s);
    largest = std::max(largest, model.kineticEnergy(s) + model.elasticEnergy(s));
  }
  PetscPrintf(PETSC_COMM_WORLD, "2000 steps at the computed step: largest energy %.3f x the initial\n", largest / e0);
  EXPECT_LT(largest, 3 * e0);
}

TEST(FemGradedMesh, ContactPressureBalancesTheTiltingMomentOfTheDrive) {
  FemParameters q = graded(24, 24, 4, 4.0);
  q.measurement.kinetic = false;  // stop at the confirmed peak
  q.slideTime = defaultSlideTime(q.eq2PeakTime(), q.measurement);  // the cap of a mu_s-only run
  q.kn = q.kt = q.plate.youngsModulus * q.nz / q.plate.thickness;  // as the uniform test (test_fem_bending.cpp)
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  const double H = q.plate.thickness, peak = q.eq2PeakTime();
  int samples = 0;
  double nextSample = 0.2 * peak;
  runPlateExperiment(model, [&](double t, Vec) {
    if (t < nextSample || t > 0.8 * peak) return;
    nextSample += 0.1 * peak;
    const ContactResultants c = contactResultants(model);
    const double ratio = c.momentAboutY / (H * std::fabs(c.forceX));
    PetscPrintf(PETSC_COMM_WORLD, "t = %.3e s: sum (x - L/2) p_c A / (H F) = %.4f; p_c trailing %.3f, centre %.3f, "
                "leading %.3f p\n", t, ratio, c.trailingEdgePressure / q.plate.pressure,
                c.centrePressure / q.plate.pressure, c.leadingEdgePressure / q.plate.pressure);
    EXPECT_NEAR(ratio, 1.0, 0.02) << "at t = " << t;
    EXPECT_LT(c.trailingEdgePressure, c.centrePressure);
    EXPECT_GT(c.leadingEdgePressure, c.centrePressure);
    ++samples;
  });
  EXPECT_GE(samples, 4);
}
