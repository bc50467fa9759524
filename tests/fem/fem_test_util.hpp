#pragma once
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

namespace gradfric::fem::test {

// The paper's material (or the plate given: the derived defaults follow it) on a small mesh.
inline FemParameters coarse(int nx, int ny, int nz, const Plate& plate = Plate{}) {
  FemParameters q(plate);
  q.nx = nx;
  q.ny = ny;
  q.nz = nz;
  q.verbose = false;
  return q;
}

inline Grading noGrading() { return Grading{}; }

inline Grading linear(GradedProperty property, double delta) {
  Grading g;
  g.profile = GradingProfile::Linear;
  g.property = property;
  g.delta = delta;
  g.bands = 10;
  return g;
}

}  // namespace gradfric::fem::test

#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/plate_model.hpp"

#include <functional>

namespace gradfric::fem::test {

// Sets the state of every owned node from its position: fill(x, y, z, u[3], v[3]).
inline void setState(const PlateModel& model, Vec X,
                     const std::function<void(const double*, double*, double*)>& fill) {
  Vec coords = nullptr;
  DMGetCoordinates(model.dm(), &coords);  // owned vertices in the same order as the state blocks
  const PetscScalar* x = nullptr;
  PetscScalar* s = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(X, &n);
  VecGetArrayRead(coords, &x);
  VecGetArray(X, &s);
  for (PetscInt b = 0; b < n / 6; ++b) fill(x + 3 * b, s + 6 * b, s + 6 * b + 3);
  VecRestoreArray(X, &s);
  VecRestoreArrayRead(coords, &x);
}

// Reduction over owned nodes of a function of (position, u, v): returns the global sum.
inline double sumOverNodes(const PlateModel& model, Vec X,
                           const std::function<double(const double*, const double*, const double*)>& term) {
  Vec coords = nullptr;
  DMGetCoordinates(model.dm(), &coords);
  const PetscScalar *x = nullptr, *s = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(X, &n);
  VecGetArrayRead(coords, &x);
  VecGetArrayRead(X, &s);
  double local = 0;
  for (PetscInt b = 0; b < n / 6; ++b) local += term(x + 3 * b, s + 6 * b, s + 6 * b + 3);
  VecRestoreArrayRead(X, &s);
  VecRestoreArrayRead(coords, &x);
  double sum = 0;
  MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, model.comm());
  return sum;
}

// The patch test's field: u = A x at every node of the displacement DM's global vector u, and the
// stress of its uniform strain (sym A) for modulus E and Poisson ratio nu.
inline void setLinearDisplacement(DM dmU, Vec u, const double (&A)[3][3]) {
  Vec coords = nullptr;
  DMGetCoordinates(dmU, &coords);  // global coordinates, same layout as u (3 per vertex)
  const PetscScalar* x = nullptr;
  PetscScalar* uu = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(u, &n);
  VecGetArrayRead(coords, &x);
  VecGetArray(u, &uu);
  for (PetscInt i = 0; i < n; i += 3)
    for (int c = 0; c < 3; ++c) uu[i + c] = A[c][0] * x[i] + A[c][1] * x[i + 1] + A[c][2] * x[i + 2];
  VecRestoreArray(u, &uu);
  VecRestoreArrayRead(coords, &x);
}

inline void uniformStress(double E, double nu, const double (&A)[3][3], double (&sigma)[3][3]) {
  const Lame l = lameFromYoung(E, nu);
  double eps[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) eps[i][j] = 0.5 * (A[i][j] + A[j][i]);
  const double tr = eps[0][0] + eps[1][1] + eps[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sigma[i][j] = 2 * l.mu * eps[i][j] + (i == j ? l.lambda * tr : 0.0);
}

}  // namespace gradfric::fem::test
