#pragma once
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

namespace gradfric::fem::test {

// The paper's material on a small plate.
inline FemParameters coarse(int nx, int ny, int nz) {
  FemParameters q;
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

}  // namespace gradfric::fem::test
