// The production kernel. Per RK stage, one sweep over the rows: the forces on row r are complete
// once the springs to row r+1 are added, so the stage update of row r follows at once, while the
// row is still in cache; the springs to row r+1 leave their reaction in a carry buffer. Every
// spring is evaluated once per stage. Loops run along a row over structure-of-arrays data and
// vectorise; the stick/slip transitions, which branch, sit in a short scalar loop of their own.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/kernel_isa.hpp"
#include "gradfric/sbm/quiet_phase.hpp"
#include "gradfric/sbm/spring.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GF_KERNEL_ISA_CLONES 1
#define GF_TARGET(isa) __attribute__((target(isa)))
#else
#define GF_KERNEL_ISA_CLONES 0
#define GF_TARGET(isa)
#endif
#define GF_ALWAYS_INLINE __attribute__((always_inline)) inline

namespace gradfric::sbm {

namespace {

// cos and sin of an angle in degrees, exact at multiples of 90 degrees.
void directionOf(double degrees, double& cx, double& cy) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns)) {
    static const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
    const int q = ((static_cast<long long>(turns) % 4) + 4) % 4;
    cx = c[q];
    cy = s[q];
    return;
  }
  cx = std::cos(degrees * M_PI / 180.0);
  cy = std::sin(degrees * M_PI / 180.0);
}

}  // namespace

Motion motionOf(const Parameters& p, double timeStep, double damping) {
  double cx, cy;
  directionOf(p.plate.slidingAngle, cx, cy);
  return {timeStep, damping, p.blockMass(), p.plate.velocity * cx, p.plate.velocity * cy, p.integrator, p.skipIdle};
}

template <class Law>
FastLattice<Law>::FastLattice(const LatticeStiffness& stiffness, Law law, const Motion& motion)
    : stiffness_(stiffness), law_(std::move(law)), motion_(motion), nb_(stiffness.blocksPerSide) {
  const std::size_t n = std::size_t(nb_) * nb_;
  for (auto* v : {&ux_, &uy_, &vx_, &vy_, &sx_, &sy_, &svx_, &svy_, &accUx_, &accUy_, &accVx_, &accVy_, &mobile_,
                 &frictionX_, &frictionY_})
    v->assign(n, 0.0);
  state_.assign(n, Stuck);
  everSlipped_.assign(n, 0);
  for (auto* v : {&fx_, &fy_, &carryX_, &carryY_, &nextX_, &nextY_, &springX_, &springY_})
    v->assign(nb_, 0.0);
  if (motion_.skipIdle) {
    quietUntil_ = firstSlipStepAtRest(stiffness_, law_, motion_, std::int64_t(1) << 52);
    quietSumX_.assign(kQuietBatch, 0.0);
    quietSumY_.assign(kQuietBatch, 0.0);
    if (motion_.integrator == Integrator::VelocityVerlet) {
      tiles_ = (nb_ + kTile - 1) / kTile;
      for (auto* v : {&pieceHx_, &pieceHy_, &pieceVx_, &pieceVy_, &pieceDx_, &pieceDy_, &pieceAx_, &pieceAy_})
        v->assign(n, 0.0);
      pieceStep_.assign(std::size_t(nb_) * tiles_, -1);
      mobileStep_.assign(std::size_t(nb_) * tiles_, -1);
    }
  }
}

namespace {

// The springs from row r (rx, ry) to row r+1 (qx, qy): vertical, diagonal (c -> c+1 above) and
// anti-diagonal (c+1 -> c above). Adds their forces to row r (fx, fy) and writes the reactions on
// row r+1 into (nextX, nextY). The arrays are distinct: __restrict lets the loops vectorise.
template <bool Graded, bool Small>
GF_ALWAYS_INLINE void springsToRowAbove(int nb, double l, double diagonalLength, const double* __restrict kV,
                                        const double* __restrict kD, const double* __restrict rx,
                                        const double* __restrict ry, const double* __restrict qx,
                                        const double* __restrict qy, double* __restrict fx, double* __restrict fy,
                                        double* __restrict nextX, double* __restrict nextY) {
  const double kV0 = kV[0], kD0 = kD[0];
  for (int c = 0; c < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kV[c] : kV0, 0.0, l, l, qx[c] - rx[c], qy[c] - ry[c]);
    fx[c] += ax;
    fy[c] += ay;
    nextX[c] = -ax;
    nextY[c] = -ay;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kD[c] : kD0, l, l, diagonalLength, qx[c + 1] - rx[c], qy[c + 1] - ry[c]);
    fx[c] += ax;
    fy[c] += ay;
    nextX[c + 1] -= ax;
    nextY[c + 1] -= ay;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kD[c] : kD0, -l, l, diagonalLength, qx[c] - rx[c + 1], qy[c] - ry[c + 1]);
    fx[c + 1] += ax;
    fy[c + 1] += ay;
    nextX[c] -= ax;
    nextY[c] -= ay;
  }
}

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

// The internal springs of one row: its horizontal springs and those to the row above.
struct RowSprings {
  int nb;
  bool above;  // a row above exists
  double l, diagonalLength;
  const double* kH;
  const double* kV;
  const double* kD;
  const double* rx;  // positions of the row (the row above follows at + nb)
  const double* ry;
  double* hx;  // horizontal spring forces (work space)
  double* hy;
  double* fx;  // forces on the row
  double* fy;
  double* nextX;  // reactions on the row above
  double* nextY;
};

// Adds the row's springs to its forces, in the kernel's fixed order (horizontal, then the springs
// to the row above).
template <bool Graded, bool Small>
GF_ALWAYS_INLINE void rowSprings(const RowSprings& s) {
  const int nb = s.nb;
  const double l = s.l;
  const double* __restrict kH = s.kH;
  const double* __restrict rx = s.rx;
  const double* __restrict ry = s.ry;
  double* __restrict hx = s.hx;
  double* __restrict hy = s.hy;
  double* __restrict fx = s.fx;
  double* __restrict fy = s.fy;
  const double kH0 = kH[0];
  for (int c = 0; c + 1 < nb; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kH[c] : kH0, l, 0.0, l, rx[c + 1] - rx[c], ry[c + 1] - ry[c]);
    hx[c] = f.x;
    hy[c] = f.y;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    fx[c] += hx[c];
    fy[c] += hy[c];
  }
  for (int c = 0; c + 1 < nb; ++c) {
    fx[c + 1] -= hx[c];
    fy[c + 1] -= hy[c];
  }
  if (s.above)
    springsToRowAbove<Graded, Small>(nb, l, s.diagonalLength, s.kV, s.kD, rx, ry, rx + nb, ry + nb, fx, fy, s.nextX,
                                     s.nextY);
}

// The springs a tile of the active set owns (columns c0 <= c < c1 of row r): horizontal, and
// with a row above vertical, diagonal and anti-diagonal, stored as pieces.
struct TilePieces {
  double* hx;
  double* hy;
  double* vx;
  double* vy;
  double* dx;
  double* dy;
  double* ax;
  double* ay;
};

template <bool Graded, bool Small>
GF_ALWAYS_INLINE void tileSprings(int c0, int c1, int springEnd, bool above, double l, double diagonalLength,
                                  const double* __restrict kH, const double* __restrict kV,
                                  const double* __restrict kD, const double* __restrict rx,
                                  const double* __restrict ry, const double* __restrict qx,
                                  const double* __restrict qy, TilePieces p) {
  const double kH0 = kH[0], kV0 = kV[0], kD0 = kD[0];
  double* __restrict hx = p.hx;
  double* __restrict hy = p.hy;
  double* __restrict vx = p.vx;
  double* __restrict vy = p.vy;
  double* __restrict dx = p.dx;
  double* __restrict dy = p.dy;
  double* __restrict ax = p.ax;
  double* __restrict ay = p.ay;
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kH[c] : kH0, l, 0.0, l, rx[c + 1] - rx[c], ry[c + 1] - ry[c]);
    hx[c] = f.x;
    hy[c] = f.y;
  }
  if (!above) return;
  for (int c = c0; c < c1; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kV[c] : kV0, 0.0, l, l, qx[c] - rx[c], qy[c] - ry[c]);
    vx[c] = f.x;
    vy[c] = f.y;
  }
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f =
        latticeSpringForce<Small>(Graded ? kD[c] : kD0, l, l, diagonalLength, qx[c + 1] - rx[c], qy[c + 1] - ry[c]);
    dx[c] = f.x;
    dy[c] = f.y;
  }
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f =
        latticeSpringForce<Small>(Graded ? kD[c] : kD0, -l, l, diagonalLength, qx[c] - rx[c + 1], qy[c] - ry[c + 1]);
    ax[c] = f.x;
    ay[c] = f.y;
  }
}

}  // namespace

// Forces F_mot on row r at positions (px, py) and time t into fx_, fy_: slider springs, the
// reactions carried from the row below, the row's horizontal springs and the springs to the row
// above (whose reactions go to next*). With WantSum, adds the slider forces to (sumX, sumY).
template <class Law>
template <bool Graded, bool WantSum>
GF_ALWAYS_INLINE void FastLattice<Law>::rowForces(int r, const double* px, const double* py, double t, const double* carryX,
                                             const double* carryY, double* nextX, double* nextY, double& sumX,
                                             double& sumY) {
  const int nb = nb_;
  const double l = stiffness_.spacing;
  const double diagonalLength = std::sqrt(2.0) * l;
  const double drivenX = motion_.sliderVelocityX * t;
  const double drivenY = motion_.sliderVelocityY * t;
  const double* kH = stiffness_.horizontal.data();
  const double* kS = stiffness_.slider.data();
  const double kS0 = kS[0];
  double* __restrict fx = fx_.data();
  double* __restrict fy = fy_.data();
  double* __restrict hx = springX_.data();
  double* __restrict hy = springY_.data();
  const double* __restrict rx = px + r * nb;
  const double* __restrict ry = py + r * nb;
  for (int c = 0; c < nb; ++c) {
    const double k = Graded ? kS[c] : kS0;
    fx[c] = k * (drivenX - rx[c]) + carryX[c];
    fy[c] = k * (drivenY - ry[c]) + carryY[c];
  }
  if (WantSum) {  // the macroscopic friction force: the sum of the slider forces
    // In registers: through the references every addition would wait on a store and a load.
    double x = sumX, y = sumY;
    for (int c = 0; c < nb; ++c) {
      const double k = Graded ? kS[c] : kS0;
      x += k * (drivenX - rx[c]);
      y += k * (drivenY - ry[c]);
    }
    sumX = x;
    sumY = y;
  }
  const RowSprings springs{nb, r + 1 < nb, l, diagonalLength, kH, stiffness_.vertical.data(), stiffness_.diagonal.data(),
                           rx, ry, hx, hy, fx, fy, nextX, nextY};
  if (stiffness_.smallStrain) rowSprings<Graded, true>(springs);
  else rowSprings<Graded, false>(springs);
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
  std::uint8_t* state = state_.data() + base;
  double* mobile = mobile_.data() + base;
  double* vx = vx_.data() + base;
  double* vy = vy_.data() + base;
  for (int c = 0; c < nb; ++c) {
    each(c);
    if (state[c] == Slipping) continue;
    const double threshold = L == SiteLayout::Uniform ? staticStrength[0] : staticStrength[c];
    switch (stickSlipChange(state[c], Law::holds(fx[c] * fx[c] + fy[c] * fy[c], threshold))) {
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
  for (int c = 0; c < c1 - c0; ++c) {
    const double strength = L == SiteLayout::Uniform ? staticStrength[0] : staticStrength[c];
    const double kinetic = L == SiteLayout::Uniform ? kineticStrength[0] : kineticStrength[c];
    const double speed2 = vx[c] * vx[c] + vy[c] * vy[c];
    const double force2 = fx[c] * fx[c] + fy[c] * fy[c];
    const bool moving = speed2 > 0.0;
    const double dirX = moving ? vx[c] : fx[c];
    const double dirY = moving ? vy[c] : fy[c];
    const double frictionPerNorm = frictionPerDirection(law_, strength, kinetic, mobile[c], speed2, force2);
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

// One sweep over the rows at positions (px, py): once row r's forces are complete (fx_, fy_),
// update(r) advances that row while it is in cache; the springs to the next row leave their
// reactions in a carry buffer.
template <class Law>
template <bool Graded, bool WantSum, class RowUpdate>
GF_ALWAYS_INLINE void FastLattice<Law>::sweepRows(const double* px, const double* py, double t, double& sumX, double& sumY,
                                             RowUpdate update) {
  const int nb = nb_;
  double* carryX = carryX_.data();
  double* carryY = carryY_.data();
  double* nextX = nextX_.data();
  double* nextY = nextY_.data();
  std::fill(carryX, carryX + nb, 0.0);
  std::fill(carryY, carryY + nb, 0.0);
  for (int r = 0; r < nb; ++r) {
    this->template rowForces<Graded, WantSum>(r, px, py, t, carryX, carryY, nextX, nextY, sumX, sumY);
    update(r);
    std::swap(carryX, nextX);
    std::swap(carryY, nextY);
  }
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

// Velocity Verlet, one force evaluation per step, fused in one sweep: with F(u_n) of a row
// complete, close the previous step's kick (v_n = v_{n-1/2} + h/2 a_n, friction and damping of
// that step), decide the stick/slip transitions at t_n, open this step's kick
// (v_{n+1/2} = v_n + h/2 a_n) and drift (u_{n+1} = u_n + h v_{n+1/2}). Damping is evaluated with
// the velocity at hand (explicit). vx_, vy_ hold the half-step velocity between steps.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletStep(double t, double& sumX, double& sumY) {
  const int nb = nb_;
  const double half = 0.5 * motion_.timeStep;
  const double h = motion_.timeStep;
  const double invMass = 1.0 / motion_.mass;
  const double gamma = motion_.damping;
  double* carryX = carryX_.data();
  double* carryY = carryY_.data();
  double* nextX = nextX_.data();
  double* nextY = nextY_.data();
  std::fill(carryX, carryX + nb, 0.0);
  std::fill(carryY, carryY + nb, 0.0);
  for (int r = 0; r < nb; ++r) {
    const int base = r * nb;
    this->template rowForces<Graded, true>(r, ux_.data(), uy_.data(), t, carryX, carryY, nextX, nextY, sumX, sumY);
    const int sites = L == SiteLayout::PerSite ? base : 0;
    const VerletRow row{fx_.data(),
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
    if (verletRowUpdate<Law, L>(law_, nb, half, h, invMass, gamma, row)) syncStates(r, t);
    std::swap(carryX, nextX);
    std::swap(carryY, nextY);
  }
}

// After the fused update changed a stick state in row r: the states (Stuck where mobile is zero)
// and the first slips of blocks that slip for the first time, at t_n.
template <class Law>
void FastLattice<Law>::syncStates(int r, double t) {
  const int base = r * nb_;
  for (int c = 0; c < nb_; ++c) {
    const int i = base + c;
    const bool slips = mobile_[i] != 0.0;
    state_[i] = slips ? Slipping : Stuck;
    if (slips && !everSlipped_[i]) {
      everSlipped_[i] = 1;
      ++slipped_;
      if (firstSlip_) firstSlip_[i] = t;
    }
  }
}

// Velocity Verlet on the active set (see integrator.hpp): the same step as verletStep, with the
// springs of still tiles taken from where they were last evaluated and the kicks, the reversal
// test and the friction vector skipped in tiles without a slipping block (on a stuck block,
// velocity zero and mobile zero, they change nothing). Every force is assembled from the same
// spring values in the same order as rowForces: bit for bit the full sweep.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletStepActive(double t, double& sumX, double& sumY) {
  const int nb = nb_, tiles = tiles_;
  const std::int64_t n = steps_;
  const double half = 0.5 * motion_.timeStep;
  const double h = motion_.timeStep;
  const double invMass = 1.0 / motion_.mass;
  const double gamma = motion_.damping;
  const double l = stiffness_.spacing;
  const double diagonalLength = std::sqrt(2.0) * l;
  const double drivenX = motion_.sliderVelocityX * t;
  const double drivenY = motion_.sliderVelocityY * t;
  const double* kH = stiffness_.horizontal.data();
  const double* kV = stiffness_.vertical.data();
  const double* kD = stiffness_.diagonal.data();
  const double* kS = stiffness_.slider.data();
  const double kS0 = kS[0];
  double* carryX = carryX_.data();
  double* carryY = carryY_.data();
  double* nextX = nextX_.data();
  double* nextY = nextY_.data();
  std::fill(carryX, carryX + nb, 0.0);
  std::fill(carryY, carryY + nb, 0.0);
  double* __restrict fx = fx_.data();
  double* __restrict fy = fy_.data();
  int stale = 0;
  for (int r = 0; r < nb; ++r) {
    const int base = r * nb;
    const bool above = r + 1 < nb;
    const double* __restrict rx = ux_.data() + base;
    const double* __restrict ry = uy_.data() + base;
    const double* __restrict qx = rx + nb;
    const double* __restrict qy = ry + nb;
    double* __restrict hx = pieceHx_.data() + base;
    double* __restrict hy = pieceHy_.data() + base;
    double* __restrict vx = pieceVx_.data() + base;
    double* __restrict vy = pieceVy_.data() + base;
    double* __restrict dx = pieceDx_.data() + base;
    double* __restrict dy = pieceDy_.data() + base;
    double* __restrict ax = pieceAx_.data() + base;
    double* __restrict ay = pieceAy_.data() + base;
    const std::int64_t* mobileHere = mobileStep_.data() + r * tiles;
    const std::int64_t* mobileAbove = above ? mobileHere + tiles : mobileHere;
    // Re-evaluate the springs of the tiles whose pieces are stale.
    for (int tile = 0; tile < tiles; ++tile) {
      std::int64_t& evaluated = pieceStep_[r * tiles + tile];
      const int right = std::min(tile + 1, tiles - 1);
      const std::int64_t moved = std::max(std::max(mobileHere[tile], mobileHere[right]),
                                          std::max(mobileAbove[tile], mobileAbove[right]));
      if (evaluated >= 0 && moved < evaluated) continue;
      evaluated = n;
      ++stale;
      const int c0 = tile * kTile, c1 = std::min(c0 + kTile, nb), springEnd = std::min(c1, nb - 1);
      const TilePieces pieces{hx, hy, vx, vy, dx, dy, ax, ay};
      if (stiffness_.smallStrain)
        tileSprings<Graded, true>(c0, c1, springEnd, above, l, diagonalLength, kH, kV, kD, rx, ry, qx, qy, pieces);
      else tileSprings<Graded, false>(c0, c1, springEnd, above, l, diagonalLength, kH, kV, kD, rx, ry, qx, qy, pieces);
    }
    // Assemble F_mot of the row and the reactions on the row above as rowForces does.
    for (int c = 0; c < nb; ++c) {
      const double k = Graded ? kS[c] : kS0;
      fx[c] = k * (drivenX - rx[c]) + carryX[c];
      fy[c] = k * (drivenY - ry[c]) + carryY[c];
    }
    for (int c = 0; c + 1 < nb; ++c) {
      fx[c] += hx[c];
      fy[c] += hy[c];
    }
    for (int c = 0; c + 1 < nb; ++c) {
      fx[c + 1] -= hx[c];
      fy[c + 1] -= hy[c];
    }
    if (above) {
      for (int c = 0; c < nb; ++c) {
        fx[c] += vx[c];
        fy[c] += vy[c];
        nextX[c] = -vx[c];
        nextY[c] = -vy[c];
      }
      for (int c = 0; c + 1 < nb; ++c) {
        fx[c] += dx[c];
        fy[c] += dy[c];
        nextX[c + 1] -= dx[c];
        nextY[c + 1] -= dy[c];
      }
      for (int c = 0; c + 1 < nb; ++c) {
        fx[c + 1] += ax[c];
        fy[c + 1] += ay[c];
        nextX[c] -= ax[c];
        nextY[c] -= ay[c];
      }
    }
    // The slider-force sum in the kernel's order (the positions are still u_n), then the row's
    // update as in verletStep. On a tile without a slipping block it changes nothing (velocity
    // and mobile zero); it is one vector pass over the row, cheaper than sorting the tiles out.
    double x = sumX, y = sumY;
    for (int c = 0; c < nb; ++c) {
      const double k = Graded ? kS[c] : kS0;
      x += k * (drivenX - rx[c]);
      y += k * (drivenY - ry[c]);
    }
    sumX = x;
    sumY = y;
    const int sites = L == SiteLayout::PerSite ? base : 0;
    const VerletRow update{fx,
                           fy,
                           law_.sites.staticStrength.data() + sites,
                           law_.sites.kineticStrength.data() + sites,
                           mobile_.data() + base,
                           vx_.data() + base,
                           vy_.data() + base,
                           ux_.data() + base,
                           uy_.data() + base,
                           frictionX_.data() + base,
                           frictionY_.data() + base};
    if (verletRowUpdate<Law, L>(law_, nb, half, h, invMass, gamma, update)) syncStates(r, t);
    std::int64_t* mobileRow = mobileStep_.data() + r * tiles;
    const std::uint8_t* state = state_.data() + base;  // Stuck = 0: mobile where non-zero
    for (int tile = 0; tile < tiles; ++tile) {
      const int c0 = tile * kTile, c1 = std::min(c0 + kTile, nb);
      bool slips = false;
      if (c1 - c0 == kTile) {
        std::uint64_t word;
        static_assert(kTile == sizeof word, "one tile of states in one word");
        std::memcpy(&word, state + c0, sizeof word);
        slips = word != 0;
      } else {
        for (int c = c0; c < c1; ++c) slips |= state[c] != Stuck;
      }
      if (slips) mobileRow[tile] = n;
    }
    std::swap(carryX, nextX);
    std::swap(carryY, nextY);
  }
  staleTiles_ = stale;
}

namespace {

template <class Law, bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void fullStep(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                               double& sumX, double& sumY) {
  if (active) {
    lattice.template verletStepActive<Graded, L>(t, sumX, sumY);
    return;
  }
  if (verlet) {
    lattice.template verletStep<Graded, L>(t, sumX, sumY);
    return;
  }
  lattice.template rk4Stage<Graded, L, 1>(t, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 2>(t + 0.5 * h, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 3>(t + 0.5 * h, sumX, sumY);
  lattice.template rk4Stage<Graded, L, 4>(t + h, sumX, sumY);
}

// One compiled entry per law x (uniform|graded stiffness) x (friction layout), each compiled for
// AVX-512, AVX2 and baseline x86-64; the one the processor supports best is chosen at run time
// (kernel_isa.hpp: a test may force each in turn to check that they agree bit for bit).
template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx512f") void stepAvx512(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                     double& sumX, double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}
template <class Law, bool Graded, SiteLayout L>
GF_TARGET("avx2") void stepAvx2(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h,
                                double& sumX, double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}
template <class Law, bool Graded, SiteLayout L>
void stepBaseline(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h, double& sumX, double& sumY) {
  fullStep<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY);
}

template <class Law, bool Graded, SiteLayout L>
void stepVariant(FastLattice<Law>& lattice, bool verlet, bool active, double t, double h, double& sumX, double& sumY) {
  switch (kernelIsaInUse()) {
    case KernelIsa::Avx512: stepAvx512<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
    case KernelIsa::Avx2: stepAvx2<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
    default: stepBaseline<Law, Graded, L>(lattice, verlet, active, t, h, sumX, sumY); return;
  }
}

template <class Law, bool Graded>
void stepLayout(FastLattice<Law>& lattice, SiteLayout layout, bool verlet, bool active, double t, double h,
                double& sumX, double& sumY) {
  if (layout == SiteLayout::Uniform)
    stepVariant<Law, Graded, SiteLayout::Uniform>(lattice, verlet, active, t, h, sumX, sumY);
  else if (layout == SiteLayout::PerColumn)
    stepVariant<Law, Graded, SiteLayout::PerColumn>(lattice, verlet, active, t, h, sumX, sumY);
  else stepVariant<Law, Graded, SiteLayout::PerSite>(lattice, verlet, active, t, h, sumX, sumY);
}

}  // namespace

template <class Law>
void FastLattice<Law>::dispatch(double& sumX, double& sumY) {
  const double t = time();
  const double h = motion_.timeStep;
  const bool verlet = motion_.integrator == Integrator::VelocityVerlet;
  const bool active = useActiveSet();
  if (active) ++activeSetSteps_;
  if (stiffness_.graded) stepLayout<Law, true>(*this, law_.sites.layout, verlet, active, t, h, sumX, sumY);
  else stepLayout<Law, false>(*this, law_.sites.layout, verlet, active, t, h, sumX, sumY);
}

// The active set pays while few tiles are stale; once more than half of them are, the full sweep
// is cheaper (no pieces to store): switch, and look again every kModeCheck steps whether fewer
// than a quarter of the tiles hold a slipping block.
template <class Law>
bool FastLattice<Law>::useActiveSet() {
  constexpr int kModeCheck = 16;
  if (!motion_.skipIdle || motion_.integrator != Integrator::VelocityVerlet) return false;
  const int total = nb_ * tiles_;
  if (activeMode_) {
    if (steps_ > nextModeCheck_ && 2 * staleTiles_ > total) {
      activeMode_ = false;
      nextModeCheck_ = steps_ + kModeCheck;
    }
    return activeMode_;
  }
  if (steps_ < nextModeCheck_) return false;
  int slipping = 0;
  for (int r = 0; r < nb_; ++r)
    for (int tile = 0; tile < tiles_; ++tile) {
      const double* mobile = mobile_.data() + r * nb_ + tile * kTile;
      const int w = std::min(kTile, nb_ - tile * kTile);
      for (int c = 0; c < w; ++c)
        if (mobile[c] != 0.0) {
          ++slipping;
          break;
        }
    }
  if (4 * slipping >= total) {
    nextModeCheck_ = steps_ + kModeCheck;
    return false;
  }
  // Enter: every piece stale, every tile possibly moved in the last step (full sweep).
  activeMode_ = true;
  nextModeCheck_ = steps_ + 1;  // the first active step evaluates every tile: do not judge it
  std::fill(pieceStep_.begin(), pieceStep_.end(), -1);
  std::fill(mobileStep_.begin(), mobileStep_.end(), steps_ - 1);
  return true;
}

template <class Law>
StepObservation FastLattice<Law>::step() {
  StepObservation observation{time(), 0.0, 0.0};
  if (steps_ < quietUntil_) {  // at rest: nothing to integrate, the sums are known
    if (quietBatchStart_ < 0 || steps_ >= quietBatchStart_ + kQuietBatch) {
      quietBatchStart_ = steps_;
      restSliderForceSums(stiffness_, motion_, steps_, quietSumX_.data(), quietSumY_.data());
    }
    observation.sliderForceX = quietSumX_[steps_ - quietBatchStart_];
    observation.sliderForceY = quietSumY_[steps_ - quietBatchStart_];
    ++steps_;
    return observation;
  }
  dispatch(observation.sliderForceX, observation.sliderForceY);
  ++steps_;
  return observation;
}

namespace {
KernelIsa forcedIsa = KernelIsa::Automatic;

KernelIsa bestIsa() {
#if GF_KERNEL_ISA_CLONES
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return KernelIsa::Avx512;
  if (__builtin_cpu_supports("avx2")) return KernelIsa::Avx2;
#endif
  return KernelIsa::Baseline;
}
}  // namespace

bool kernelIsaSupported(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Automatic:
    case KernelIsa::Baseline: return true;
    case KernelIsa::Avx2: return bestIsa() != KernelIsa::Baseline;
    case KernelIsa::Avx512: return bestIsa() == KernelIsa::Avx512;
  }
  return false;
}

bool forceKernelIsa(KernelIsa isa) {
  if (!kernelIsaSupported(isa)) return false;
  forcedIsa = isa;
  return true;
}

KernelIsa kernelIsaInUse() {
  static const KernelIsa best = bestIsa();
  return forcedIsa == KernelIsa::Automatic ? best : forcedIsa;
}

const char* kernelIsaName(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::Avx512: return "avx512f";
    case KernelIsa::Avx2: return "avx2";
    case KernelIsa::Baseline: return "baseline x86-64";
    default: return "automatic";
  }
}

#define GF_INSTANTIATE_FAST_LATTICE(Law) template class FastLattice<Law>;
GF_FRICTION_LAWS(GF_INSTANTIATE_FAST_LATTICE)
#undef GF_INSTANTIATE_FAST_LATTICE

}  // namespace gradfric::sbm
