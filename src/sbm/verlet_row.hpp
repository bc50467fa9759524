#pragma once
// Private to the fast spring-block kernel: velocity Verlet's fused step of one row, shared by the
// full sweep (full_sweep.hpp) and the active set (active_set.hpp): the row's driving forces
// assembled from its springs' values (RowPieces, row_springs.hpp), then the whole update, in one
// pass; and the one builder of the row's arrays (FastLattice::verletRow).
#include "block_state.hpp"
#include "gradfric/sbm/integrator.hpp"
#include "row_springs.hpp"
#include "slider_sum.hpp"

#include <cmath>
#include <cstdint>

namespace gradfric::sbm {

// The reaction on row r+1 at column c of the springs row r owns, from its vertical v[c], diagonal
// d[c-1] and anti-diagonal a[c]: -v[c] - d[c-1] - a[c], as both the fused and the held step write
// it.
GF_ALWAYS_INLINE double reactionAbove(double vertical, double diagonalLeft, double antiDiagonal) {
  double reaction = -vertical;
  reaction -= diagonalLeft;
  reaction -= antiDiagonal;
  return reaction;
}

// The per-block arrays of one row that the fused Verlet step reads and writes.
struct VerletRow {
  const double* __restrict slider;  // slider stiffness per column (element 0 without grading)
  const double* __restrict carryX;  // reactions of the springs from the row below
  const double* __restrict carryY;
  RowPieces pieces;
  double* __restrict nextX;  // reactions on the row above (written when there is one)
  double* __restrict nextY;
  double* __restrict sliderX;  // the row's slider forces at t_n, for the history's sum
  double* __restrict sliderY;
  const double* __restrict staticStrength;  // offset to the row (per site) or the columns
  const double* __restrict kineticStrength;
  double* __restrict mobile;
  double* __restrict vx;
  double* __restrict vy;
  double* __restrict ux;
  double* __restrict uy;
  double* __restrict kfx;  // friction of the last step on entry, of this step on exit
  double* __restrict kfy;
  // Laws with a per-block state only (null otherwise; block_state.hpp): theta, the position at the
  // start of the last step, the strength at the state of this step.
  double* __restrict theta = nullptr;
  double* __restrict startX = nullptr;
  double* __restrict startY = nullptr;
  double* __restrict strength = nullptr;
};

// Velocity Verlet's whole step of one row in one pass, branch-free so that it vectorises: the
// driving force F_mot at t_n (slider, carried reactions, the row's springs, in the order
// slider + carry + h[c] - h[c-1] + v[c] + d[c] + a[c-1], and the reactions on the row above
// -v[c] - d[c-1] - a[c]), then close the last step's kick, the reversal test against that step's
// friction, with a per-block state its advance (block_state.hpp: the threshold and the sliding
// force are then the block's strength), the stick/slip decision at t_n (as blends: a stuck block
// that the threshold does not hold starts to slip, a reversed one that it holds re-sticks at zero
// velocity), this step's friction vector, the open kick and the drift (v_{n+1/2} = v_n + h/2
// a_n, u_{n+1} = u_n + h v_{n+1/2}), for the columns c0 <= c < c1. Returns whether one of those blocks started to slip
// (the caller looks for first slips).
template <class Law, SiteLayout L, bool Graded, bool Above>
GF_ALWAYS_INLINE bool fusedVerletRow(const Law& law, int c0, int c1, double drivenX, double drivenY, double half,
                                    double h, double invMass, double gamma, VerletRow a) {
  const double* __restrict slider = a.slider;
  const double* __restrict carryX = a.carryX;
  const double* __restrict carryY = a.carryY;
  const double* __restrict hx = a.pieces.hx;
  const double* __restrict hy = a.pieces.hy;
  const double* __restrict pvx = a.pieces.vx;
  const double* __restrict pvy = a.pieces.vy;
  const double* __restrict dx = a.pieces.dx;
  const double* __restrict dy = a.pieces.dy;
  const double* __restrict ax = a.pieces.ax;
  const double* __restrict ay = a.pieces.ay;
  double* __restrict nextX = a.nextX;
  double* __restrict nextY = a.nextY;
  double* __restrict sliderX = a.sliderX;
  double* __restrict sliderY = a.sliderY;
  const double* __restrict staticStrength = a.staticStrength;
  const double* __restrict kineticStrength = a.kineticStrength;
  double* __restrict mobile = a.mobile;
  double* __restrict vx = a.vx;
  double* __restrict vy = a.vy;
  double* __restrict ux = a.ux;
  double* __restrict uy = a.uy;
  double* __restrict kfx = a.kfx;
  double* __restrict kfy = a.kfy;
  double* __restrict theta = a.theta;
  double* __restrict startX = a.startX;
  double* __restrict startY = a.startY;
  double* __restrict strength = a.strength;
  double decay = 0.0;
  if constexpr (hasBlockState<Law>) decay = law.decayOver(h);
  const double slider0 = slider[0];
  std::int64_t started = 0;
  for (int c = c0; c < c1; ++c) {
    // F_mot at t_n.
    const double k = Graded ? slider[c] : slider0;
    const double sx = sliderForce(k, drivenX, ux[c]);
    const double sy = sliderForce(k, drivenY, uy[c]);
    sliderX[c] = sx;
    sliderY[c] = sy;
    double fxc = sx + carryX[c];
    double fyc = sy + carryY[c];
    fxc += hx[c];
    fyc += hy[c];
    fxc -= hx[c - 1];
    fyc -= hy[c - 1];
    if (Above) {
      fxc += pvx[c];
      fyc += pvy[c];
      fxc += dx[c];
      fyc += dy[c];
      fxc += ax[c - 1];
      fyc += ay[c - 1];
      nextX[c] = reactionAbove(pvx[c], dx[c - 1], ax[c]);
      nextY[c] = reactionAbove(pvy[c], dy[c - 1], ay[c]);
    }
    // The update.
    const double m = mobile[c];
    const double oldKx = kfx[c], oldKy = kfy[c];
    double wx = vx[c] + half * m * ((fxc - oldKx) * invMass - gamma * vx[c]);
    double wy = vy[c] + half * m * ((fyc - oldKy) * invMass - gamma * vy[c]);
    const bool reversed = wx * oldKx + wy * oldKy < 0.0;
    double threshold = L == SiteLayout::Uniform ? staticStrength[0] : staticStrength[c];
    const double kinetic = L == SiteLayout::Uniform ? kineticStrength[0] : kineticStrength[c];
    if constexpr (hasBlockState<Law>) {
      threshold = advanceBlockState(law, h, decay, threshold, kinetic, ux[c], uy[c], startX[c], startY[c], theta[c]);
      strength[c] = threshold;
    }
    const double force2 = fxc * fxc + fyc * fyc;
    const bool holds = holdsAtRest<Law>(force2, threshold);
    const bool starts = (m == 0.0) & !holds;
    const bool resticks = reversed & holds;
    const double newM = starts ? 1.0 : resticks ? 0.0 : m;
    wx = resticks ? 0.0 : wx;
    wy = resticks ? 0.0 : wy;
    started |= std::int64_t(starts);
    // The friction vector (frictionPerDirection, written without a branch around the division;
    // moving, the speed and the norm are one square root).
    const double speed2 = wx * wx + wy * wy;
    const bool moving = speed2 > 0.0;
    const double dirX = moving ? wx : fxc;
    const double dirY = moving ? wy : fyc;
    const double norm2 = moving ? speed2 : force2;
    const bool directed = norm2 > 0.0;
    const double norm = std::sqrt(directed ? norm2 : 1.0);
    double sliding;
    if constexpr (hasBlockState<Law>) sliding = threshold;  // the block's strength
    else sliding = law.slidingStrength(threshold, kinetic, Law::weakensWithSpeed && moving ? norm : 0.0);
    const double perNorm = (directed ? newM * sliding : 0.0) / norm;
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
  return started != 0;
}

// The same step for columns c0 <= c < c1 of held tiles (the active set's, slip_prediction.hpp):
// their blocks are stuck and provably hold at t_n, so the update leaves them as they are (zero
// velocity, no drift; the friction vector, +-0 for a stuck block, is never read while it stays
// stuck). Only what the rest of the sweep reads is written, with fusedVerletRow's expressions
// (sliderForce, reactionAbove): the slider forces (the history's sum) and the reactions on the
// row above.
template <bool Graded, bool Above>
GF_ALWAYS_INLINE void heldVerletRow(int c0, int c1, double drivenX, double drivenY, VerletRow a) {
  const double* __restrict slider = a.slider;
  const double* __restrict pvx = a.pieces.vx;
  const double* __restrict pvy = a.pieces.vy;
  const double* __restrict dx = a.pieces.dx;
  const double* __restrict dy = a.pieces.dy;
  const double* __restrict ax = a.pieces.ax;
  const double* __restrict ay = a.pieces.ay;
  const double* __restrict ux = a.ux;
  const double* __restrict uy = a.uy;
  double* __restrict sliderX = a.sliderX;
  double* __restrict sliderY = a.sliderY;
  double* __restrict nextX = a.nextX;
  double* __restrict nextY = a.nextY;
  const double slider0 = slider[0];
  for (int c = c0; c < c1; ++c) {
    const double k = Graded ? slider[c] : slider0;
    sliderX[c] = sliderForce(k, drivenX, ux[c]);
    sliderY[c] = sliderForce(k, drivenY, uy[c]);
    if (Above) {
      nextX[c] = reactionAbove(pvx[c], dx[c - 1], ax[c]);
      nextY[c] = reactionAbove(pvy[c], dy[c - 1], ay[c]);
    }
  }
}

// Row r's arrays for fusedVerletRow, with its springs in `pieces`.
template <class Law>
template <SiteLayout L>
GF_ALWAYS_INLINE VerletRow FastLattice<Law>::verletRow(int r, const RowPieces& pieces) {
  const int base = r * nb_;
  const int sites = L == SiteLayout::PerSite ? base : 0;
  VerletRow row{stiffness_.row(r).slider,
                carryX_.data(),
                carryY_.data(),
                pieces,
                nextX_.data(),
                nextY_.data(),
                sliderRowX_.data(),
                sliderRowY_.data(),
                law_.sites.staticStrength.data() + sites,
                law_.sites.kineticStrength.data() + sites,
                mobile_.data() + base,
                vx_.data() + base,
                vy_.data() + base,
                ux_.data() + base,
                uy_.data() + base,
                frictionX_.data() + base,
                frictionY_.data() + base};
  if constexpr (hasBlockState<Law>) {
    row.theta = law_.state.data() + base;
    row.startX = startX_.data() + base;
    row.startY = startY_.data() + base;
    row.strength = strength_.data() + base;
  }
  return row;
}

// Row r's whole Verlet step on its springs' pieces (the full sweep): the fused step, then
// finishRow.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletRowStep(int r, const RowPieces& pieces, double t, double& sumX,
                                                      double& sumY) {
  const VerletRow row = this->template verletRow<L>(r, pieces);
  const bool started = this->template verletColumns<Graded, L>(r, row, 0, nb_, t);
  finishRow(r, t, started, sumX, sumY);
}

// The fused step of columns [c0, c1) of row r at t_n (whether a block started to slip).
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE bool FastLattice<Law>::verletColumns(int r, const VerletRow& row, int c0, int c1, double t) {
  const double half = 0.5 * motion_.timeStep;
  const double drivenX = motion_.sliderVelocityX * t;
  const double drivenY = motion_.sliderVelocityY * t;
  return r + 1 < nb_ ? fusedVerletRow<Law, L, Graded, true>(law_, c0, c1, drivenX, drivenY, half, motion_.timeStep,
                                                            1.0 / motion_.mass, motion_.damping, row)
                     : fusedVerletRow<Law, L, Graded, false>(law_, c0, c1, drivenX, drivenY, half, motion_.timeStep,
                                                             1.0 / motion_.mass, motion_.damping, row);
}

// After row r's step (both sweeps): its slider forces added to the history's sums (slider_sum.hpp), the first slips of the blocks that started, and the reactions on the row above handed
// on as the next row's carry.
template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::finishRow(int r, double t, bool started, double& sumX, double& sumY) {
  const int nb = nb_;
  sumX += rowSum(sliderRowX_.data(), nb);
  sumY += rowSum(sliderRowY_.data(), nb);
  if (started && slipped_ < nb * nb) firstSlips(r, t);
  carryX_.swap(nextX_);
  carryY_.swap(nextY_);
}

}  // namespace gradfric::sbm
