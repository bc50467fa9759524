#pragma once
// Damping of the plate's vibrations once it slides (docs/accuracy_fem.md, "The defaults and
// why"). The release of the stored shear at the static peak rings the plate's thickness-shear
// and rocking modes (omega_1 = pi c_s / (2H)) with a bottom velocity far above the sliding speed;
// undamped, the plate bounces (normal force +-10 %, nodes lifting off) and does not slide steadily
// even with constant friction.
//
// The remedy is mass-proportional damping measured in the slider's frame,
//   a_damping = -gamma_lab v - gamma_slider (v - v_slider),   v_slider = v (cos theta, sin theta, 0),
// switched on once the static peak is confirmed (so mu_s is untouched bit for bit): it damps every
// vibration relative to the rigidly sliding plate, strongest in the slowest modes, and exerts no
// force at all in steady sliding (every node moves at v_slider), so neither the friction nor the
// normal force of the steady state is biased. A dashpot towards rest (gamma_lab,
// -fem_slide_damping) drags by gamma rho H v instead. It does not remove the node-scale
// stick-slip of Eq. 1 alone (a stopped node is back at mu_s); the friction law's healing length
// does (physics/slip_state_law.hpp, -fem_slip_length): see the docs. Pure arithmetic, no PETSc.
namespace gradfric::fem {

struct SlidingDamping {
  double lab = 0.0;       // gamma_lab [1/s]: towards rest (-fem_slide_damping, or c_s/H while settling)
  double slider = 0.0;    // gamma_slider [1/s]: towards the slider's velocity (0 until the peak)
  double sliderVelocity[3] = {0.0, 0.0, 0.0};  // [m/s]

  // The damping acceleration of velocity component d [m/s^2].
  double acceleration(const double* velocity, int d) const {
    return -lab * velocity[d] - slider * (velocity[d] - sliderVelocity[d]);
  }
  // The power the damping takes from a node of mass m [W] (force . velocity, positive).
  double power(double mass, const double* velocity) const {
    double p = 0.0;
    for (int d = 0; d < 3; ++d) p -= mass * acceleration(velocity, d) * velocity[d];
    return p;
  }
};

}  // namespace gradfric::fem
