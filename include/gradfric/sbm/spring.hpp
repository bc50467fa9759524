#pragma once
// Pointwise force of one lattice spring (paper: F = k (r_ij - l_ij) (r_j - r_i) / r_ij).
// Written with displacements so that small strains keep their digits: the extension is
// (|d|^2 - L0^2) / (|d| + L0), which has no cancellation when |d| is close to L0.
#include <cmath>

namespace gradfric::sbm {

struct Force2 {
  double x, y;
};

// Force on block i from the spring to block j. rest = (restX, restY) is r_j^0 - r_i^0 with length
// restLength; (dux, duy) = u_j - u_i. Tension (positive extension) pulls i towards j. Returned by
// value: out-parameters would keep the callers' loops from vectorising.
inline Force2 springForce(double k, double restX, double restY, double restLength, double dux, double duy) {
  const double dx = restX + dux;
  const double dy = restY + duy;
  const double length = std::sqrt(dx * dx + dy * dy);
  const double extensionTimesSum = 2.0 * (restX * dux + restY * duy) + dux * dux + duy * duy;
  const double scale = k * extensionTimesSum / (length * (length + restLength));
  return {scale * dx, scale * dy};
}

// The same spring linearised about its rest direction (small strain): F = k (e . du) e with the
// unit vector e = (unitX, unitY) from i to j at rest. No square root, no division.
inline Force2 smallStrainSpringForce(double k, double unitX, double unitY, double dux, double duy) {
  const double scale = k * (unitX * dux + unitY * duy);
  return {scale * unitX, scale * unitY};
}

// One spring of the lattice, exact or small strain (chosen at compile time in the kernels).
template <bool SmallStrain>
inline Force2 latticeSpringForce(double k, double restX, double restY, double restLength, double dux, double duy) {
  if constexpr (SmallStrain) return smallStrainSpringForce(k, restX / restLength, restY / restLength, dux, duy);
  else return springForce(k, restX, restY, restLength, dux, duy);
}

}  // namespace gradfric::sbm
