#pragma once
// Friction laws as small policy objects, pure arithmetic, no PETSc.
#include <cmath>

namespace gradfric {

// Amontons-Coulomb with distinct static and kinetic coefficients (the SBM's law): a block at rest
// holds while |F_mot| <= mu_s F_n; a sliding block feels mu_k F_n against its velocity.
struct CoulombStickSlip {
  double muStatic;
  double muKinetic;
  double staticThreshold(double normalForce) const { return muStatic * normalForce; }
  double kineticForce(double normalForce) const { return muKinetic * normalForce; }
  bool holds(double drivingForceSquared, double normalForce) const {
    const double threshold = staticThreshold(normalForce);
    return drivingForceSquared <= threshold * threshold;
  }
};

// The paper's Eq. 1 (the FEM's law): mu(v) = mu_k + (mu_s - mu_k) exp(-v / v_c).
struct ExponentialVelocityWeakening {
  double muStatic;
  double muKinetic;
  double criticalVelocity;  // v_c > 0
  double coefficient(double slipSpeed) const {
    return muKinetic + (muStatic - muKinetic) * std::exp(-slipSpeed / criticalVelocity);
  }
};

}  // namespace gradfric
