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
