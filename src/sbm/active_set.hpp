#pragma once
// Private to the fast spring-block kernel: velocity Verlet on the active set (integrator.hpp,
// FastLattice's tiles): only the springs of tiles near a moving block are evaluated again, and
// tiles that provably stay stuck (held, slip_prediction.hpp) are left out of the update.
#include "gradfric/sbm/slip_prediction.hpp"
#include "row_springs.hpp"
#include "verlet_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace gradfric::sbm {

// For every tile of row r, the last step a block of the tiles around it (itself included) was
// mobile, into movedAround_: the positions its forces read (its springs, those of its left
// neighbour, the carry from the row below) are those of these blocks.
template <class Law>
GF_ALWAYS_INLINE void FastLattice<Law>::lastMovedAround(int r) {
  const int tiles = tiles_;
  const std::int64_t* below = mobileStep_.data() + std::size_t(std::max(r - 1, 0)) * tiles;
  const std::int64_t* here = mobileStep_.data() + std::size_t(r) * tiles;
  const std::int64_t* above = mobileStep_.data() + std::size_t(std::min(r + 1, nb_ - 1)) * tiles;
  std::int64_t* column = columnMoved_.data();
  std::int64_t* around = movedAround_.data();
  for (int tile = 0; tile < tiles; ++tile) column[tile] = std::max(std::max(below[tile], here[tile]), above[tile]);
  for (int tile = 0; tile < tiles; ++tile)
    around[tile] = std::max(std::max(column[std::max(tile - 1, 0)], column[tile]), column[std::min(tile + 1, tiles - 1)]);
}

// Velocity Verlet on the active set (see integrator.hpp): the same step as verletStep, with the
// springs of still tiles taken from where they were last evaluated (they are the same numbers:
// their blocks have not moved), and held tiles stepped by heldVerletRow (their update changes
// nothing). The row step of the other tiles is the full sweep's (fusedVerletRow), on the same
// spring values: bit for bit the full sweep.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletStepActive(double t, double& sumX, double& sumY) {
  const int nb = nb_, tiles = tiles_;
  const std::int64_t n = steps_;
  const double drivenX = motion_.sliderVelocityX * t;
  const double drivenY = motion_.sliderVelocityY * t;
  std::fill(carryX_.begin(), carryX_.end(), 0.0);
  std::fill(carryY_.begin(), carryY_.end(), 0.0);
  int stale = 0;
  for (int r = 0; r < nb; ++r) {
    const bool above = r + 1 < nb;
    const RowPieces pieces = keptPieces(r);
    std::int64_t* mobileRow = mobileStep_.data() + r * tiles;
    const std::int64_t* mobileAbove = above ? mobileRow + tiles : mobileRow;
    std::uint8_t* held = heldRow_.data();
    const std::int64_t* around = movedAround_.data();
    lastMovedAround(r);
    for (int tile = 0; tile < tiles; ++tile) {
      // Re-evaluate the springs of the tile if they are stale.
      std::int64_t& evaluated = pieceStep_[r * tiles + tile];
      const int right = std::min(tile + 1, tiles - 1);
      const std::int64_t moved = std::max(std::max(mobileRow[tile], mobileRow[right]),
                                          std::max(mobileAbove[tile], mobileAbove[right]));
      if (evaluated < 0 || moved >= evaluated) {
        evaluated = n;
        ++stale;
        this->template ownSprings<Graded>(r, tile * kTile, std::min(tile * kTile + kTile, nb), pieces);
      }
      // Held this step: proven to hold from the state at holdFrom_ on, and nothing around it
      // moved since.
      const std::size_t i = std::size_t(r) * tiles + tile;
      held[tile] = holdUntil_[i] > n && around[tile] < holdFrom_[i];
    }
    // The row's step: what the sweep reads of every block (heldVerletRow, one pass over the row:
    // short loops would not fill the vectors), then the fused step on the runs of tiles not held,
    // which writes the same slider forces and reactions again and updates the blocks.
    const VerletRow row = this->template verletRow<L>(r, pieces);
    if (above) heldVerletRow<Graded, true>(0, nb, drivenX, drivenY, row);
    else heldVerletRow<Graded, false>(0, nb, drivenX, drivenY, row);
    bool started = false;
    for (int tile = 0; tile < tiles;) {
      int end = tile + 1;
      while (end < tiles && held[end] == held[tile]) ++end;
      if (!held[tile]) {
        started |= this->template verletColumns<Graded, L>(r, row, tile * kTile, std::min(end * kTile, nb), t);
      } else {
        heldTileSteps_ += end - tile;
        healHeldStates(r, tile * kTile, std::min(end * kTile, nb));  // state laws: they heal (block_state.hpp)
      }
      tile = end;
    }
    const double* mobile = mobile_.data() + r * nb;
    for (int tile = 0; tile < tiles; ++tile) {
      if (held[tile]) continue;
      const int c0 = tile * kTile, c1 = std::min(c0 + kTile, nb);
      bool slips = false;
      for (int c = c0; c < c1; ++c) slips |= mobile[c] != 0.0;
      if (slips) mobileRow[tile] = n;
    }
    this->template holdTiles<Graded, L>(r, row);
    finishRow(r, t, started, sumX, sumY);
  }
  staleTiles_ = stale;
}

// After row r's step at t_n: the tiles of the row that are all stuck, with nothing around them
// moving at t_n, hold until the first step at which one of their blocks might start to slip
// (holdsUntil, from the forces' constant part at u_n and the slider's rate). Reads this row's
// carry, so it runs before finishRow hands it on.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::holdTiles(int r, const VerletRow& row) {
  constexpr std::int64_t kNever = std::int64_t(1) << 52;
  if (!motion_.fixedStrengths) return;  // a threshold that changes between steps proves nothing
  const int nb = nb_, tiles = tiles_;
  const std::int64_t n = steps_;
  const bool above = r + 1 < nb;
  const double dt = motion_.timeStep, vx = motion_.sliderVelocityX, vy = motion_.sliderVelocityY;
  const RowPieces& p = row.pieces;
  const std::int64_t* mobileRow = mobileStep_.data() + std::size_t(r) * tiles;
  for (int tile = 0; tile < tiles; ++tile) {
    if (heldRow_[tile] || movedAround_[tile] >= n) continue;
    // Around it, nothing moved before this step (movedAround_) nor in it (this row's new marks;
    // the row below was marked before, the row above moves at the earliest in the next step).
    const std::int64_t movedNow =
        std::max(std::max(mobileRow[std::max(tile - 1, 0)], mobileRow[tile]), mobileRow[std::min(tile + 1, tiles - 1)]);
    if (movedNow >= n) continue;
    const std::size_t i = std::size_t(r) * tiles + tile;
    const int c0 = tile * kTile, c1 = std::min(c0 + kTile, nb);
    std::int64_t until = kNever;
    for (int c = c0; c < c1 && until > n + 1; ++c) {
      const double k = Graded ? row.slider[c] : row.slider[0];
      // With a per-block state, the strength of this step: it only rises while the block rests.
      const double threshold = hasBlockState<Law>       ? row.strength[c]
                               : L == SiteLayout::Uniform ? row.staticStrength[0]
                                                          : row.staticStrength[c];
      double cx = row.carryX[c] + p.hx[c] - p.hx[c - 1], cy = row.carryY[c] + p.hy[c] - p.hy[c - 1];
      double scale = std::abs(row.carryX[c]) + std::abs(p.hx[c]) + std::abs(p.hx[c - 1]) + std::abs(row.carryY[c]) +
                     std::abs(p.hy[c]) + std::abs(p.hy[c - 1]);
      if (above) {
        cx += p.vx[c] + p.dx[c] + p.ax[c - 1];
        cy += p.vy[c] + p.dy[c] + p.ay[c - 1];
        scale += std::abs(p.vx[c]) + std::abs(p.dx[c]) + std::abs(p.ax[c - 1]) + std::abs(p.vy[c]) +
                 std::abs(p.dy[c]) + std::abs(p.ay[c - 1]);
      }
      const double kux = k * row.ux[c], kuy = k * row.uy[c];
      const AffineDrivingForce force{cx - kux, cy - kuy, k * vx, k * vy, scale + std::abs(kux) + std::abs(kuy)};
      until = std::min(until, holdsUntil(force, threshold, dt, n + 1, kNever));
    }
    holdFrom_[i] = n;
    holdUntil_[i] = until;
  }
}

}  // namespace gradfric::sbm
