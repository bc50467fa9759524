#pragma once
// Private to the fast spring-block kernel: the per-block state of a law that keeps one (the state
// law; reference_lattice.hpp states the rule). Each block's theta is advanced once per step, at
// its start t_n, from its displacement increment over the step that ended, with the law's own
// functions in the reference kernel's order (the slip of the increment, slipOf, then
// evolveBySlip, strengthBetween) and committed at once (a block's update reads only its own
// state). The strength at the new state is the block's static threshold and sliding force.
//
// Held tiles (active_set.hpp) are not stepped, but their states are: their blocks are stuck, so
// their slip is exactly 0 and the full sweep's update is pure healing, theta e^(-v_c dt / D_c).
// healHeldStates applies that same update (the same call, zero slip) every step, with no
// exponential, so the active set stays the full sweep bit for bit. Healing only raises a block's
// strength, so a tile proven to hold at its strengths when it was held still holds while it heals.
// The quiet phase needs nothing: until the first slip every theta is 0 and stays 0.
#include "gradfric/sbm/integrator.hpp"
#include "kernel_inline.hpp"

#include <cmath>

namespace gradfric::sbm {

// One block's state over the step dt (healing factor decay) that ended: from its position now
// (ux, uy) and at the start of that step (startX, startY, moved on to now); returns its strength
// at the new state, between its static and kinetic strengths s and k.
template <class Law>
GF_ALWAYS_INLINE double advanceBlockState(const Law& law, double dt, double decay, double s, double k, double ux,
                                          double uy, double& startX, double& startY, double& theta) {
  const double slip = slipOf(ux - startX, uy - startY);
  startX = ux;
  startY = uy;
  theta = law.evolveBySlip(theta, slip, dt, decay);
  return law.strengthBetween(s, k, theta);
}

// RK4: the states of row r at t_n, before its stick/slip transitions (Verlet does this inside its
// fused row step, fusedVerletRow).
template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::advanceStates(int r) {
  if constexpr (hasBlockState<Law>) {
    const double dt = motion_.timeStep, decay = law_.decayOver(dt);
    const int base = r * nb_;
    for (int c = 0; c < nb_; ++c) {
      const int i = base + c, slot = law_.sites.slot(r, c);
      strength_[i] = advanceBlockState(law_, dt, decay, law_.sites.staticAt(slot), law_.sites.kineticAt(slot), ux_[i],
                                       uy_[i], startX_[i], startY_[i], law_.state[i]);
    }
  }
}

// The held blocks c0 <= c < c1 of row r: the update at zero slip (see above). Their strength_
// stays that of the step they were held at: only the hold proof reads it, and held tiles are not
// proven again.
template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::healHeldStates(int r, int c0, int c1) {
  if constexpr (hasBlockState<Law>) {
    const double dt = motion_.timeStep, decay = law_.decayOver(dt);
    double* theta = law_.state.data() + r * nb_;
    for (int c = c0; c < c1; ++c) theta[c] = law_.evolveBySlip(theta[c], 0.0, dt, decay);
  }
}

}  // namespace gradfric::sbm
