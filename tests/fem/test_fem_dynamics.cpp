// Explicit dynamics without contact: energy conservation and the compressional wave speed.
#include <petscsection.h>
#include <petscsf.h>
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/verlet_ts.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

TEST(FemDynamics, FreePlateKeepsItsEnergyOver1000VerletSteps) {
  Plate unloaded;
  unloaded.pressure = 0;
  FemParameters q = test::coarse(8, 8, 3, unloaded);
  q.contact = false;
  q.settleDamping = 0;
  q.slideDamping = 0;
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  OwnedVec X(model.createState());
  // A smooth bending-and-stretching velocity field plus an initial strain.
  test::setState(model, X, [&](const double* x, double* u, double* v) {
    const double sx = std::sin(M_PI * x[0] / q.plate.length), cy = std::cos(M_PI * x[1] / q.plate.length);
    u[0] = 1e-8 * sx * cy;
    u[1] = 0;
    u[2] = 0;
    v[0] = 0;
    v[1] = 1e-4 * sx;
    v[2] = 1e-3 * sx * cy * (x[2] / q.plate.thickness);
  });
  // Velocity Verlet conserves a shadow energy: the computed energy oscillates by O((omega dt)^2)
  // in the stiff thickness modes but must not drift. Drift = change of the mean over 100 steps
  // between the first and the last 100 steps.
  OwnedTS ts(createPlateTS(model, X));
  auto energy = [&]() {
    Vec s = nullptr;
    TSGetSolution(ts, &s);
    return model.kineticEnergy(s) + model.elasticEnergy(s);
  };
  const double e0 = energy();
  double first = 0, last = 0, maxDeviation = 0;
  for (int step = 1; step <= 1000; ++step) {
    ASSERT_EQ(TSStep(ts), 0);
    const double e = energy();
    if (step <= 100) first += e / 100;
    if (step > 900) last += e / 100;
    maxDeviation = std::max(maxDeviation, std::fabs(e - e0) / e0);
  }
  const double drift = std::fabs(last - first) / first;
  PetscPrintf(PETSC_COMM_WORLD, "energy: drift %.3e, largest deviation %.3e over 1000 steps\n", drift, maxDeviation);
  EXPECT_LT(drift, 0.01) << "relative energy drift " << drift;
  EXPECT_LT(maxDeviation, 0.05) << "largest deviation from the initial energy " << maxDeviation;
  // The test would catch a wrong mass or a non-symplectic update: energy must also not be trivial.
  EXPECT_GT(e0, 0.0);
}

TEST(FemDynamics, CompressionalPulseTravelsAtTheWaveSpeed) {
  // nu = 0: a uniaxial pulse u_x(x - c t) stays uniaxial, c = sqrt(E / rho) exactly.
  Plate unloaded;
  unloaded.poissonRatio = 0.0;
  unloaded.pressure = 0;
  FemParameters q = test::coarse(240, 1, 1, unloaded);
  q.contact = false;
  q.settleDamping = 0;
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  const double c = std::sqrt(q.plate.youngsModulus / q.plate.density);
  const double x0 = 0.25 * q.plate.length, w = 0.04 * q.plate.length;
  OwnedVec X(model.createState());
  test::setState(model, X, [&](const double* x, double* u, double* v) {
    const double s = (x[0] - x0) / w, g = std::exp(-s * s);
    u[0] = 1e-9 * g;
    v[0] = -c * 1e-9 * g * (-2 * s / w);  // right-going: v = -c du/dx
    u[1] = u[2] = v[1] = v[2] = 0;
  });
  auto centroid = [&](Vec s) {
    const double num = test::sumOverNodes(model, s, [](const double* x, const double* u, const double*) { return x[0] * u[0] * u[0]; });
    const double den = test::sumOverNodes(model, s, [](const double*, const double* u, const double*) { return u[0] * u[0]; });
    return num / den;
  };
  const double start = centroid(X);
  OwnedTS ts(createPlateTS(model, X));
  const double travel = 0.4 * q.plate.length;
  PetscReal t = 0;
  while (t < travel / c) {
    ASSERT_EQ(TSStep(ts), 0);
    TSGetTime(ts, &t);
  }
  Vec s = nullptr;
  TSGetSolution(ts, &s);
  const double speed = (centroid(s) - start) / t;
  PetscPrintf(PETSC_COMM_WORLD, "pulse speed %.4f m/s, analytic %.4f m/s (ratio %.5f)\n", speed, c, speed / c);
  EXPECT_NEAR(speed / c, 1.0, 0.02) << "measured " << speed << " m/s, analytic " << c << " m/s";
}
