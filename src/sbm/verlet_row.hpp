#pragma once
// Private to the fast spring-block kernel: velocity Verlet's fused update of one row, shared by
// the full sweep (full_sweep.hpp) and the active set (active_set.hpp), and the one builder of the
// row's arrays (FastLattice::verletRow).
#include "gradfric/sbm/integrator.hpp"
#include "kernel_inline.hpp"

#include <cmath>
#include <cstdint>

namespace gradfric::sbm {

// The per-block arrays of one row that the fused Verlet update reads and writes; all distinct.
struct VerletRow {
  const double* __restrict fx;  // F_mot at t_n
  const double* __restrict fy;
  const double* __restrict staticStrength;   // offset to the row (per site) or the columns
  const double* __restrict kineticStrength;
  double* __restrict mobile;
  double* __restrict vx;
  double* __restrict vy;
  double* __restrict ux;
  double* __restrict uy;
  double* __restrict kfx;  // friction of the last step on entry, of this step on exit
  double* __restrict kfy;
};

// Velocity Verlet's whole update of one row in one pass, branch-free so that it vectorises: close
// the last step's kick, the reversal test against that step's friction, the stick/slip decision
// at t_n (as blends: a stuck block that the threshold does not hold starts to slip, a reversed one
// that it holds re-sticks at zero velocity), this step's friction vector, the open kick and the
// drift (v_{n+1/2} = v_n + h/2 a_n, u_{n+1} = u_n + h v_{n+1/2}). The arithmetic is that of the
// separate passes it replaced (and of markReversals, transitions and frictionVector, which RK4
// keeps), in the same order: the same numbers bit for bit. Returns whether a block
// of the row started to slip or re-stuck (the caller's bookkeeping of states and first slips).
template <class Law, SiteLayout L>
GF_ALWAYS_INLINE bool verletRowUpdate(const Law& law, int nb, double half, double h, double invMass, double gamma,
                                      VerletRow a) {
  const double* __restrict fx = a.fx;
  const double* __restrict fy = a.fy;
  const double* __restrict staticStrength = a.staticStrength;
  const double* __restrict kineticStrength = a.kineticStrength;
  double* __restrict mobile = a.mobile;
  double* __restrict vx = a.vx;
  double* __restrict vy = a.vy;
  double* __restrict ux = a.ux;
  double* __restrict uy = a.uy;
  double* __restrict kfx = a.kfx;
  double* __restrict kfy = a.kfy;
  std::int64_t changed = 0;
  for (int c = 0; c < nb; ++c) {
    const double m = mobile[c];
    const double fxc = fx[c], fyc = fy[c];
    const double oldKx = kfx[c], oldKy = kfy[c];
    double wx = vx[c] + half * m * ((fxc - oldKx) * invMass - gamma * vx[c]);
    double wy = vy[c] + half * m * ((fyc - oldKy) * invMass - gamma * vy[c]);
    const bool reversed = wx * oldKx + wy * oldKy < 0.0;
    const double threshold = L == SiteLayout::Uniform ? staticStrength[0] : staticStrength[c];
    const double kinetic = L == SiteLayout::Uniform ? kineticStrength[0] : kineticStrength[c];
    const double force2 = fxc * fxc + fyc * fyc;
    const bool holds = Law::holds(force2, threshold);
    const bool starts = (m == 0.0) & !holds;
    const bool resticks = reversed & holds;
    const double newM = starts ? 1.0 : resticks ? 0.0 : m;
    wx = resticks ? 0.0 : wx;
    wy = resticks ? 0.0 : wy;
    changed |= std::int64_t(starts | resticks);
    // The friction vector (frictionPerDirection, written without a branch around the division).
    const double speed2 = wx * wx + wy * wy;
    const bool moving = speed2 > 0.0;
    const double dirX = moving ? wx : fxc;
    const double dirY = moving ? wy : fyc;
    const double norm2 = moving ? speed2 : force2;
    const double speed = Law::weakensWithSpeed && moving ? std::sqrt(speed2) : 0.0;
    const double sliding = law.slidingStrength(threshold, kinetic, speed);
    const bool directed = norm2 > 0.0;
    const double perNorm = (directed ? newM * sliding : 0.0) / std::sqrt(directed ? norm2 : 1.0);
    const double kx = perNorm * dirX, ky = perNorm * dirY;
    // Open this step's kick and drift.
    wx += half * newM * ((fxc - kx) * invMass - gamma * wx);
    wy += half * newM * ((fyc - ky) * invMass - gamma * wy);
    mobile[c] = newM;
    kfx[c] = kx;
    kfy[c] = ky;
    vx[c] = wx;
    vy[c] = wy;
    ux[c] += h * wx;
    uy[c] += h * wy;
  }
  return changed != 0;
}

// Row r's arrays for verletRowUpdate, with its driving forces in fx_, fy_.
template <class Law>
template <SiteLayout L>
GF_ALWAYS_INLINE VerletRow FastLattice<Law>::verletRow(int r) {
  const int base = r * nb_;
  const int sites = L == SiteLayout::PerSite ? base : 0;
  return VerletRow{fx_.data(),
                   fy_.data(),
                   law_.sites.staticStrength.data() + sites,
                   law_.sites.kineticStrength.data() + sites,
                   mobile_.data() + base,
                   vx_.data() + base,
                   vy_.data() + base,
                   ux_.data() + base,
                   uy_.data() + base,
                   frictionX_.data() + base,
                   frictionY_.data() + base};
}

}  // namespace gradfric::sbm
