#pragma once
// Private to the fast spring-block kernel: velocity Verlet on the active set (integrator.hpp,
// FastLattice's tiles): only the springs of tiles near a moving block are evaluated again.
#include "row_springs.hpp"
#include "verlet_row.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace gradfric::sbm {

// Velocity Verlet on the active set (see integrator.hpp): the same step as verletStep, with the
// springs of still tiles taken from where they were last evaluated (they are the same numbers:
// their blocks have not moved). The row step (verletRowStep) is the full sweep's, on the same
// spring values: bit for bit the full sweep.
template <class Law>
template <bool Graded, SiteLayout L>
GF_ALWAYS_INLINE void FastLattice<Law>::verletStepActive(double t, double& sumX, double& sumY) {
  const int nb = nb_, tiles = tiles_;
  const std::int64_t n = steps_;
  std::fill(carryX_.begin(), carryX_.end(), 0.0);
  std::fill(carryY_.begin(), carryY_.end(), 0.0);
  int stale = 0;
  for (int r = 0; r < nb; ++r) {
    const bool above = r + 1 < nb;
    const RowPieces pieces = keptPieces(r);
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
      this->template ownSprings<Graded>(r, tile * kTile, std::min(tile * kTile + kTile, nb), pieces);
    }
    // The row's step as in verletStep, from the kept pieces. On a tile without a slipping block
    // the update changes nothing but the threshold test (velocity and mobile zero); it is one
    // vector pass over the row, cheaper than sorting the tiles out.
    this->template verletRowStep<Graded, L>(r, pieces, t, sumX, sumY);
    std::int64_t* mobileRow = mobileStep_.data() + r * tiles;
    const double* mobile = mobile_.data() + r * nb;
    for (int tile = 0; tile < tiles; ++tile) {
      const int c0 = tile * kTile, c1 = std::min(c0 + kTile, nb);
      bool slips = false;
      for (int c = c0; c < c1; ++c) slips |= mobile[c] != 0.0;
      if (slips) mobileRow[tile] = n;
    }
  }
  staleTiles_ = stale;
}

}  // namespace gradfric::sbm
