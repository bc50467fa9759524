#pragma once
// The quiet phase of a spring-block run: from rest until the first block slips, nothing moves.
// Every block stays at its initial position with zero velocity, the springs between blocks carry
// no force and the driving force of block i is its slider's alone, K_s,i v t_n. The stepped
// kernel computes exactly that (its spring forces are all +-0), so the quiet phase is known in
// closed form, bit for bit:
//   - the first step at which some block's driving force exceeds its static threshold (the
//     law's own test, Law::holds, with the law's per-site strengths);
//   - the slider-force sums of the history, summed in the kernels' order (src/sbm/slider_sum.hpp).
// FastLattice jumps over these steps (Motion::skipIdle) and integrates from the first slip on. A law
// with a per-block state keeps theta = 0 (no block slid): the thresholds are its strengths there.
#include "gradfric/sbm/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gradfric::sbm {

// The slider forces at rest at step n, as the kernel computes them: k (v t_n - 0).
inline double restSliderForce(double k, double sliderVelocity, double timeStep, std::int64_t step) {
  const double t = double(step) * timeStep;
  const double driven = sliderVelocity * t;
  return k * (driven - 0.0);
}

// The first step n at which a block at rest, slider stiffness k and static strength s, no longer
// holds (its driving force is monotone in n). At most `limit`.
template <class Law>
std::int64_t firstSlipStepAtRest(double k, double staticStrength, const Motion& m, std::int64_t limit) {
  auto holdsAt = [&](std::int64_t n) {
    const double fx = restSliderForce(k, m.sliderVelocityX, m.timeStep, n);
    const double fy = restSliderForce(k, m.sliderVelocityY, m.timeStep, n);
    return Law::holds(fx * fx + fy * fy, staticStrength);
  };
  const double speed = std::hypot(m.sliderVelocityX, m.sliderVelocityY);
  const double estimate = staticStrength / (k * speed * m.timeStep);
  std::int64_t n = std::isfinite(estimate) ? std::int64_t(std::clamp(estimate, 0.0, double(limit))) : limit;
  while (n > 0 && !holdsAt(n - 1)) --n;  // the estimate is within a few ulps: short walks
  while (n < limit && holdsAt(n)) ++n;
  return n;
}

// The first step at which some block of the lattice at rest starts to slip (at most `limit`).
template <class Law>
std::int64_t firstSlipStepAtRest(const LatticeStiffness& stiffness, const Law& law, const Motion& m,
                                 std::int64_t limit) {
  const int nb = stiffness.blocksPerSide;
  const FrictionSites& sites = law.sites;
  std::int64_t first = limit;
  for (int r = 0; r < nb; ++r) {
    for (int c = 0; c < nb; ++c) {
      const double s = sites.staticAt(sites.slot(r, c));
      first = std::min(first, firstSlipStepAtRest<Law>(stiffness.sliderAt(r, c), s, m, first));
    }
    if (sites.layout != SiteLayout::PerSite && !stiffness.perBlock) break;  // every row is the same
  }
  return first;
}

// The same with one static threshold per block (row-major, N_b^2): a law with a per-block state,
// every block at its initial strength (the shared static rule, StaticThreshold).
inline std::int64_t firstSlipStepAtRestPerBlock(const LatticeStiffness& stiffness, const std::vector<double>& thresholds,
                                                const Motion& m, std::int64_t limit) {
  const int nb = stiffness.blocksPerSide;
  std::int64_t first = limit;
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c)
      first = std::min(first, firstSlipStepAtRest<StaticThreshold>(stiffness.sliderAt(r, c), thresholds[r * nb + c], m, first));
  return first;
}

// The kernels' slider-force sums (their order, src/sbm/slider_sum.hpp) of the lattice at rest at
// `step`; row: work space [N_b].
void restSliderForceSums(const LatticeStiffness& stiffness, const Motion& m, std::int64_t step, double* row,
                         double& sumX, double& sumY);

}  // namespace gradfric::sbm
