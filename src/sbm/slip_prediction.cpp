// When a stuck block can start to slip (slip_prediction.hpp): a proposal from the quadratic, a
// proof at both ends, a bisection when the proposal fails the proof.
#include "gradfric/sbm/slip_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gradfric::sbm {

std::int64_t holdsUntil(const AffineDrivingForce& f, double staticStrength, double timeStep, std::int64_t from,
                        std::int64_t cap) {
  if (from >= cap) return cap;
  const double limit = staticStrength * (1.0 - kHoldMargin);
  const double rate = std::abs(f.bx) + std::abs(f.by);
  // Rounding of A, of A + B t here and of the kernel's sum: each a few eps of the magnitudes
  // summed (at most ~30 eps together); 64 eps keeps a factor two.
  constexpr double kRounding = 64.0 * std::numeric_limits<double>::epsilon();
  const auto provenHeld = [&](std::int64_t m) {
    const double t = double(m) * timeStep;
    const double fx = f.ax + f.bx * t, fy = f.ay + f.by * t;
    const double rounding = kRounding * (f.scale + rate * std::abs(t));
    return rounding <= 0.25 * kHoldMargin * staticStrength && fx * fx + fy * fy <= limit * limit;
  };
  if (!provenHeld(from)) return from;
  // The proposal: the last step before A + B t leaves the disc of radius `limit`.
  std::int64_t last = cap - 1;
  const double b2 = f.bx * f.bx + f.by * f.by;
  if (b2 > 0.0) {
    const double ab = f.ax * f.bx + f.ay * f.by;
    const double inside = f.ax * f.ax + f.ay * f.ay - limit * limit;
    const double discriminant = std::max(ab * ab - b2 * inside, 0.0);
    const double leaves = (-ab + std::sqrt(discriminant)) / b2 / timeStep;
    if (std::isfinite(leaves) && leaves < double(last)) last = std::max(from, std::int64_t(std::floor(leaves)));
  }
  if (provenHeld(last)) return last + 1;
  // Held at `from`, not proven at `last`: the proven steps form an interval from `from` on.
  std::int64_t held = from, notProven = last;
  while (notProven - held > 1) {
    const std::int64_t mid = held + (notProven - held) / 2;
    (provenHeld(mid) ? held : notProven) = mid;
  }
  return held + 1;
}

}  // namespace gradfric::sbm
