#pragma once
// When a stuck block that nothing around it moves can start to slip. Its driving force is then
// affine in time, F(t) = A + B t: A holds its springs and the slider's -k u (all constant), B = k v
// is the slider's rate. The kernel evaluates F with rounding and holds the block while
// |F|^2 <= s^2 (StaticThreshold). holdsUntil gives a step up to which that test provably holds,
// so the active set (src/sbm/active_set.hpp) can leave the block's tile out until then and still
// be the full sweep bit for bit:
//   - |A + B t| is convex in t, so it stays below a bound on [t_a, t_b] once it does at both ends;
//   - the ends are checked with a margin (kHoldMargin of s) that covers the rounding of A + B t
//     and of the kernel's own sum (bounded by the magnitudes it adds, `scale` and |B| t).
// The quadratic |A + B t| = s (1 - margin) only proposes the far end; the checks decide. PETSc-free.
#include <cstdint>

namespace gradfric::sbm {

struct AffineDrivingForce {
  double ax, ay;  // A [N]
  double bx, by;  // B [N/s]
  double scale;   // sum of |terms| the kernel adds up for A, both components [N] (rounding bound)
};

// Relative distance to the threshold that a held step keeps (far above the rounding, ~1e-15).
constexpr double kHoldMargin = 1e-9;

// The first step m >= from at which the kernel's static test might fail for a block driven by f
// with static strength s (steps at t_m = m dt): it holds at every step in [from, result). `from`
// itself if that cannot be proven there; at most `cap`.
std::int64_t holdsUntil(const AffineDrivingForce& f, double staticStrength, double timeStep, std::int64_t from,
                        std::int64_t cap);

}  // namespace gradfric::sbm
