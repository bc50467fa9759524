#pragma once
// Private to the fast spring-block kernel: classical RK4, four force sweeps a step, each row's
// stage update fused with its force evaluation (full_sweep.hpp, sweepRows); the stick/slip
// transitions, which branch, in a short scalar loop of their own.
#include "full_sweep.hpp"

#include <cstdint>

namespace gradfric::sbm {

// The arrays one row's RK update touches; all distinct.
struct RowArrays {
  const double* __restrict fx;
  const double* __restrict fy;
  const double* __restrict kfx;  // kinetic friction of the step
  const double* __restrict kfy;
  const double* __restrict mobile;
  double* __restrict ux;
  double* __restrict uy;
  double* __restrict vx;
  double* __restrict vy;
  double* __restrict sx;  // next stage point
  double* __restrict sy;
  double* __restrict svx;
  double* __restrict svy;
  double* __restrict aUx;  // RK accumulators
  double* __restrict aUy;
  double* __restrict aVx;
  double* __restrict aVy;
};

// RK4 stage update of one row: acceleration from the driving force, the frozen kinetic friction
// and the damping; stages 1-3 set the next stage point, stage 4 the new state.
template <int Stage>
GF_ALWAYS_INLINE void updateRow(int nb, double toNext, double sixth, double invMass, double gamma, RowArrays a) {
  const double* __restrict fx = a.fx;
  const double* __restrict fy = a.fy;
  const double* __restrict kfx = a.kfx;
  const double* __restrict kfy = a.kfy;
  const double* __restrict mobile = a.mobile;
  double* __restrict ux = a.ux;
  double* __restrict uy = a.uy;
  double* __restrict vx = a.vx;
  double* __restrict vy = a.vy;
  double* __restrict sx = a.sx;
  double* __restrict sy = a.sy;
  double* __restrict svx = a.svx;
  double* __restrict svy = a.svy;
  double* __restrict aUx = a.aUx;
  double* __restrict aUy = a.aUy;
  double* __restrict aVx = a.aVx;
  double* __restrict aVy = a.aVy;
  for (int c = 0; c < nb; ++c) {
    const double wx = Stage == 1 ? vx[c] : svx[c];  // velocity at this stage
    const double wy = Stage == 1 ? vy[c] : svy[c];
    const double m = mobile[c];
    const double ax = m * ((fx[c] - kfx[c]) * invMass - gamma * wx);
    const double ay = m * ((fy[c] - kfy[c]) * invMass - gamma * wy);
    if (Stage == 1) {
      aUx[c] = wx;
      aUy[c] = wy;
      aVx[c] = ax;
      aVy[c] = ay;
    } else if (Stage < 4) {
      aUx[c] += 2.0 * wx;
      aUy[c] += 2.0 * wy;
      aVx[c] += 2.0 * ax;
      aVy[c] += 2.0 * ay;
    }
    if (Stage < 4) {
      sx[c] = ux[c] + toNext * wx;
      sy[c] = uy[c] + toNext * wy;
      svx[c] = vx[c] + toNext * ax;
      svy[c] = vy[c] + toNext * ay;
    } else {
      ux[c] += sixth * (aUx[c] + wx);
      uy[c] += sixth * (aUy[c] + wy);
      const double newX = vx[c] + sixth * (aVx[c] + ax);
      const double newY = vy[c] + sixth * (aVy[c] + ay);
      vx[c] = newX;
      vy[c] = newY;
    }
  }
}

// Stick/slip transitions of row r with its driving forces at t_n (see integrator.hpp). Branches,
// so it runs as a short scalar loop of its own.
template <class Law>
template <SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::transitions(int r, double t) {
  this->template transitionsWith<L>(r, t, [](int) {});
}

// The same, calling each(c) first for every block c of the row in order: the active set adds
// the slider-force sum here, where its chain of dependent additions overlaps the branches.
template <class Law>
template <SiteLayout L, class PerBlock>
GF_ALWAYS_INLINE void FastLattice<Law>::transitionsWith(int r, double t, PerBlock each) {
  const int nb = nb_, base = r * nb;
  const double* fx = fx_.data();
  const double* fy = fy_.data();
  const double* staticStrength = law_.sites.staticStrength.data() + (L == SiteLayout::PerSite ? base : 0);
  const double* strength = hasBlockState<Law> ? strength_.data() + base : nullptr;  // advanceStates
  std::uint8_t* state = state_.data() + base;
  double* mobile = mobile_.data() + base;
  double* vx = vx_.data() + base;
  double* vy = vy_.data() + base;
  for (int c = 0; c < nb; ++c) {
    each(c);
    if (state[c] == Slipping) continue;
    const double threshold = hasBlockState<Law>       ? strength[c]
                             : L == SiteLayout::Uniform ? staticStrength[0]
                                                        : staticStrength[c];
    switch (stickSlipChange(state[c], holdsAtRest<Law>(fx[c] * fx[c] + fy[c] * fy[c], threshold))) {
      case StickSlipChange::StartsToSlip:
        state[c] = Slipping;
        mobile[c] = 1.0;
        if (!everSlipped_[base + c]) {
          everSlipped_[base + c] = 1;
          ++slipped_;
          if (firstSlip_) firstSlip_[base + c] = t;
        }
        break;
      case StickSlipChange::Resticks:  // reversed during the last step and held by static friction
        state[c] = Stuck;
        mobile[c] = 0.0;
        vx[c] = 0.0;
        vy[c] = 0.0;
        break;
      case StickSlipChange::SlidesOn: state[c] = Slipping; break;
      case StickSlipChange::None: break;
    }
  }
}

// The friction vector of this step for row r: the law's sliding force along the velocity at t_n,
// or along F_mot for a block starting from rest; zero for a stuck block. Frozen for the step, like
// the stick state, so that a velocity crossing zero inside the step is seen as a reversal.
template <class Law>
template <SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::frictionVector(int r) {
  this->template frictionVectorRange<L>(r, 0, nb_);
}

// The same for columns c0 <= c < c1 of row r (the active set's tiles).
template <class Law>
template <SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::frictionVectorRange(int r, int c0, int c1) {
  const int nb = nb_, base = r * nb + c0;
  const double* __restrict fx = fx_.data() + c0;
  const double* __restrict fy = fy_.data() + c0;
  const double* __restrict staticStrength =
      law_.sites.staticStrength.data() + (L == SiteLayout::PerSite ? base : L == SiteLayout::PerColumn ? c0 : 0);
  const double* __restrict kineticStrength =
      law_.sites.kineticStrength.data() + (L == SiteLayout::PerSite ? base : L == SiteLayout::PerColumn ? c0 : 0);
  const double* __restrict mobile = mobile_.data() + base;
  const double* __restrict vx = vx_.data() + base;
  const double* __restrict vy = vy_.data() + base;
  double* __restrict kfx = frictionX_.data() + base;
  double* __restrict kfy = frictionY_.data() + base;
  const double* __restrict blockStrength = hasBlockState<Law> ? strength_.data() + base : nullptr;
  for (int c = 0; c < c1 - c0; ++c) {
    const double strength = L == SiteLayout::Uniform ? staticStrength[0] : staticStrength[c];
    const double kinetic = L == SiteLayout::Uniform ? kineticStrength[0] : kineticStrength[c];
    const double speed2 = vx[c] * vx[c] + vy[c] * vy[c];
    const double force2 = fx[c] * fx[c] + fy[c] * fy[c];
    const bool moving = speed2 > 0.0;
    const double dirX = moving ? vx[c] : fx[c];
    const double dirY = moving ? vy[c] : fy[c];
    double frictionPerNorm;
    if constexpr (hasBlockState<Law>) frictionPerNorm = frictionPerDirectionAt(blockStrength[c], mobile[c], speed2, force2);
    else frictionPerNorm = frictionPerDirection(law_, strength, kinetic, mobile[c], speed2, force2);
    kfx[c] = frictionPerNorm * dirX;
    kfy[c] = frictionPerNorm * dirY;
  }
}

// A slipping block whose new velocity points against this step's friction reversed: it may
// re-stick at the next step.
template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::markReversals(int r) {
  markReversalsRange(r, 0, nb_);
}

template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::markReversalsRange(int r, int c0, int c1) {
  const int base = r * nb_;
  const double* kfx = frictionX_.data() + base;
  const double* kfy = frictionY_.data() + base;
  const double* vx = vx_.data() + base;
  const double* vy = vy_.data() + base;
  std::uint8_t* state = state_.data() + base;
  for (int c = c0; c < c1; ++c)
    if (vx[c] * kfx[c] + vy[c] * kfy[c] < 0.0) state[c] = Reversed;
}

template <class Law>
template <bool Graded, SiteLayout L, int Stage>
GF_ALWAYS_INLINE void FastLattice<Law>::rk4Stage(double t, double& sumX, double& sumY) {
  const int nb = nb_;
  const double h = motion_.timeStep;
  const double toNext = Stage == 3 ? h : 0.5 * h;  // from u_n to the next stage's point
  const double sixth = h / 6.0;
  const double invMass = 1.0 / motion_.mass;
  const double gamma = motion_.damping;
  // Positions where this stage evaluates the forces: u_n for stage 1, the stage point otherwise.
  // A row's stage point is overwritten once its forces are complete: no later row reads it.
  const double* px = Stage == 1 ? ux_.data() : sx_.data();
  const double* py = Stage == 1 ? uy_.data() : sy_.data();
  this->template sweepRows<Graded, Stage == 1>(px, py, t, sumX, sumY, [&](int r) {
    const int base = r * nb;
    if (Stage == 1) {
      advanceStates(r);  // state laws only
      this->template transitions<L>(r, t);
      this->template frictionVector<L>(r);
    }
    updateRow<Stage>(nb, toNext, sixth, invMass, gamma,
                     RowArrays{fx_.data(), fy_.data(), frictionX_.data() + base, frictionY_.data() + base,
                               mobile_.data() + base, ux_.data() + base, uy_.data() + base, vx_.data() + base,
                               vy_.data() + base, sx_.data() + base, sy_.data() + base, svx_.data() + base,
                               svy_.data() + base, accUx_.data() + base, accUy_.data() + base, accVx_.data() + base,
                               accVy_.data() + base});
    if (Stage == 4) markReversals(r);
  });
}

}  // namespace gradfric::sbm
