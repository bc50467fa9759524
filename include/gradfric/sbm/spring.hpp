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

}  // namespace gradfric::sbm
