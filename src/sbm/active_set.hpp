#pragma once
// Private to the fast spring-block kernel: velocity Verlet on the active set (integrator.hpp,
// FastLattice's tiles): only the springs of tiles near a moving block are evaluated again.
#include "row_springs.hpp"
#include "verlet_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace gradfric::sbm {

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
    const RowStiffness rowStiffness = rowStiffnessOf(stiffness_, r);
    const double* kH = rowStiffness.horizontal;
    const double* kV = rowStiffness.vertical;
    const double* kD = rowStiffness.diagonal;
    const double* kA = rowStiffness.antiDiagonal;
    const double* kS = rowStiffness.slider;
    const double kS0 = kS[0];
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
        tileSprings<Graded, true>(c0, c1, springEnd, above, l, diagonalLength, kH, kV, kD, kA, rx, ry, qx, qy, pieces);
      else tileSprings<Graded, false>(c0, c1, springEnd, above, l, diagonalLength, kH, kV, kD, kA, rx, ry, qx, qy, pieces);
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
    if (verletRowUpdate<Law, L>(law_, nb, half, h, invMass, gamma, this->template verletRow<L>(r))) syncStates(r, t);
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

}  // namespace gradfric::sbm
