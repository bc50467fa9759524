// The pure functions of the spring-block parameters (PETSc-free core).
#include "gradfric/sbm/parameters.hpp"

#include "gradfric/sbm/lattice.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::sbm {

double stableTimeStep(const Parameters& p, const Grading& grading) {
  // Highest lattice frequency: the zone-boundary mode q = (pi, 0) of the square lattice with
  // axial k and diagonal k/2 has m omega^2 = 6k + K_s (stiffest band). Classical RK4 is stable
  // on the imaginary axis up to |omega dt| = 2 sqrt(2), velocity Verlet up to omega dt = 2.
  const LatticeStiffness s = buildStiffness(p, grading);
  double largest = 0.0;
  if (!s.perBlock) {
    for (int c = 0; c < p.blocksPerSide; ++c) largest = std::max(largest, 6.0 * s.vertical[c] + s.slider[c]);
  } else {  // the stiffest block's own k_i (both K_int and K_s are proportional to E_i)
    const double axialPerSlider = p.axialStiffness(1.0) / p.sliderStiffness(1.0);
    for (double slider : s.slider) largest = std::max(largest, 6.0 * axialPerSlider * slider + slider);
  }
  const bool verlet = p.integrator == Integrator::VelocityVerlet;
  const double oscillation = (verlet ? 2.0 : 2.0 * std::sqrt(2.0)) / std::sqrt(largest / p.blockMass());
  // The damping alone, on the real axis: RK4 is stable for gamma dt <= 2.785, our explicit
  // Verlet kicks for gamma dt <= 2 (conservative).
  const double damping = p.damping > 0 ? (verlet ? 2.0 : 2.785) / p.damping : oscillation;
  return std::min(oscillation, damping);
}

double slipTime(const Parameters& p, const Grading& grading) {
  const LatticeStiffness s = buildStiffness(p, grading);
  const double stiffest = *std::max_element(s.slider.begin(), s.slider.end());
  return std::sqrt(p.blockMass() / stiffest);
}

double surfaceStepFactor(const Parameters& p) {
  if (p.surface.kind == SurfaceKind::Blocks) return 1.0;  // l_c is the block: nothing finer to resolve
  return std::min(1.0, p.spacing() / p.surfaceOf().correlationLength);
}

double defaultTimeStep(const Parameters& p, const Grading& grading) {
  return std::min(p.timeStepSafety * stableTimeStep(p, grading),
                  p.timeStepSlip * slipTime(p, grading) * surfaceStepFactor(p));
}

}  // namespace gradfric::sbm
