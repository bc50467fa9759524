#pragma once
// Private to the fast spring-block kernel: the full sweep over the rows. Once row r's forces are
// complete (the springs to row r+1 added), its update follows at once, while the row is still in
// cache; the springs to row r+1 leave their reaction in a carry buffer. Every spring is evaluated
// once per force evaluation. RK4's stages are such sweeps (sweepRows); velocity Verlet's step
// (verletStep) evaluates each row's own springs into pieces and runs its fused row pass on them.
#include "row_springs.hpp"
#include "slider_sum.hpp"
#include "verlet_row.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gradfric::sbm {

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
  const RowStiffness rowStiffness = rowStiffnessOf(stiffness_, r);
  const double* kS = rowStiffness.slider;
  const double kS0 = kS[0];
  double* __restrict fx = fx_.data();
  double* __restrict fy = fy_.data();
  double* __restrict hx = springX_.data();
  double* __restrict hy = springY_.data();
  const double* __restrict rx = px + r * nb;
  const double* __restrict ry = py + r * nb;
  for (int c = 0; c < nb; ++c) {
    const double k = Graded ? kS[c] : kS0;
    fx[c] = sliderForce(k, drivenX, rx[c]) + carryX[c];
    fy[c] = sliderForce(k, drivenY, ry[c]) + carryY[c];
  }
  // The macroscopic friction force: the sum of the slider forces (slider_sum.hpp). A loop of its
  // own: stores to both rows in one loop keep some of the compiled versions from vectorising.
  if (WantSum) {
    double* __restrict sx = sliderRowX_.data();
    double* __restrict sy = sliderRowY_.data();
    for (int c = 0; c < nb; ++c) {
      const double k = Graded ? kS[c] : kS0;
      sx[c] = sliderForce(k, drivenX, rx[c]);
      sy[c] = sliderForce(k, drivenY, ry[c]);
    }
    sumX += rowSum(sx, nb);
    sumY += rowSum(sy, nb);
  }
  const RowSprings springs{nb, r + 1 < nb, l, diagonalLength, rowStiffness.horizontal, rowStiffness.vertical,
                           rowStiffness.diagonal, rowStiffness.antiDiagonal, rx, ry, hx, hy, fx, fy, nextX, nextY};
  if (stiffness_.smallStrain) rowSprings<Graded, true>(springs);
  else rowSprings<Graded, false>(springs);
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

// The springs columns c0 <= c < c1 of row r own (tileSprings), evaluated at u_n into its pieces:
// the full sweep's whole row, or one stale tile of the active set.
template <class Law>
template <bool Graded>
GF_ALWAYS_INLINE void FastLattice<Law>::ownSprings(int r, int c0, int c1, const RowPieces& pieces) {
  const int nb = nb_;
  const double l = stiffness_.spacing;
  const double diagonalLength = std::sqrt(2.0) * l;
  const RowStiffness s = rowStiffnessOf(stiffness_, r);
  const double* rx = ux_.data() + r * nb;
  const double* ry = uy_.data() + r * nb;
  const bool above = r + 1 < nb;
  const int springEnd = std::min(c1, nb - 1);
  if (stiffness_.smallStrain)
    tileSprings<Graded, true>(c0, c1, springEnd, above, l, diagonalLength, s.horizontal, s.vertical, s.diagonal,
                              s.antiDiagonal, rx, ry, rx + nb, ry + nb, pieces);
  else
    tileSprings<Graded, false>(c0, c1, springEnd, above, l, diagonalLength, s.horizontal, s.vertical, s.diagonal,
                               s.antiDiagonal, rx, ry, rx + nb, ry + nb, pieces);
}

// Velocity Verlet, one force evaluation per step, in one sweep over the rows: row r's springs
// (those it owns: horizontal and to the row above) are evaluated at u_n into the row's pieces,
// then its whole step follows (verletRowStep: forces, the closing kick of the last step, the
// stick/slip transitions at t_n, the opening kick and the drift) while the row is in cache.
// vx_, vy_ hold the half-step velocity between steps.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletStep(double t, double& sumX, double& sumY) {
  const int nb = nb_;
  std::fill(carryX_.begin(), carryX_.end(), 0.0);
  std::fill(carryY_.begin(), carryY_.end(), 0.0);
  const RowPieces pieces = rowPieces();
  for (int r = 0; r < nb; ++r) {
    this->template ownSprings<Graded>(r, 0, nb, pieces);
    this->template verletRowStep<Graded, L>(r, pieces, t, sumX, sumY);
  }
}

}  // namespace gradfric::sbm
