// holdsUntil (slip_prediction.hpp), the proof behind the active set's held tiles: the step it
// returns is never later than the first step at which the kernel's own arithmetic lets a block
// slip, and for a crossing that is not grazing it is at most two steps early.
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/sbm/slip_prediction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

// A stuck block as the kernel sees it (fusedVerletRow): slider k, position u, slider velocity v,
// six constant spring terms added in the kernel's order.
struct Block {
  double k, ux, uy, vx, vy;
  double termsX[6], termsY[6];

  bool holdsAt(std::int64_t m, double timeStep, double s) const {
    const double t = double(m) * timeStep;
    const double drivenX = vx * t, drivenY = vy * t;
    double fx = k * (drivenX - ux), fy = k * (drivenY - uy);
    for (int j = 0; j < 6; ++j) {
      fx += termsX[j];
      fy += termsY[j];
    }
    return StaticThreshold::holds(fx * fx + fy * fy, s);
  }
  // As the active set builds it (active_set.hpp, holdTiles).
  AffineDrivingForce force() const {
    double cx = 0, cy = 0, scale = 0;
    for (int j = 0; j < 6; ++j) {
      cx += termsX[j];
      cy += termsY[j];
      scale += std::abs(termsX[j]) + std::abs(termsY[j]);
    }
    const double kux = k * ux, kuy = k * uy;
    return {cx - kux, cy - kuy, k * vx, k * vy, scale + std::abs(kux) + std::abs(kuy)};
  }
};

// The first step >= from at which the kernel lets the block slip (brute force), at most cap.
std::int64_t firstFailure(const Block& b, double dt, double s, std::int64_t from, std::int64_t cap) {
  for (std::int64_t m = from; m < cap; ++m)
    if (!b.holdsAt(m, dt, s)) return m;
  return cap;
}

}  // namespace

TEST(SlipPrediction, NeverLateAndAtMostTwoStepsEarlyOnRandomBlocks) {
  // Paper-like magnitudes: k ~ 1e3 N/m, mu_s F_n ~ 0.1 N, u ~ 1e-5 m, v = 0.1 m/s, dt ~ 3e-8 s;
  // springs pulling in any direction, sliding at any angle, crossings a few thousand steps away.
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double dt = 3e-8, s = 0.1;
  int crossings = 0, tight = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Block b{};
    b.k = 1e3 * (1.5 + unit(random));
    const double angle = M_PI * unit(random);
    b.vx = 0.1 * std::cos(angle);
    b.vy = 0.1 * std::sin(angle);
    b.ux = 1e-5 * unit(random);
    b.uy = 1e-5 * unit(random);
    for (int j = 0; j < 6; ++j) {
      b.termsX[j] = 0.05 * unit(random);
      b.termsY[j] = 0.05 * unit(random);
    }
    const std::int64_t from = 100 + std::int64_t(200 * (1 + unit(random)));
    const std::int64_t cap = 20000;
    const std::int64_t until = holdsUntil(b.force(), s, dt, from, cap);
    const std::int64_t failure = firstFailure(b, dt, s, from, cap);
    ASSERT_LE(until, failure) << "trial " << trial << ": held past the kernel's first slip";
    if (until > from && failure < cap) {
      ++crossings;
      if (failure - until <= 2) ++tight;
    }
  }
  // Most blocks start inside the disc and leave it within the cap; a grazing crossing (the force
  // nearly perpendicular to the slider at |F| = s) may be proven much earlier, and rarely is.
  EXPECT_GT(crossings, 500);
  EXPECT_GT(tight, 0.99 * crossings);
}

TEST(SlipPrediction, DecidesTheClearCases) {
  const double dt = 1e-8, s = 1.0;
  // No slider motion: the force never changes, the block holds for ever (up to the cap).
  EXPECT_EQ(holdsUntil({0.5, 0.0, 0.0, 0.0, 1.0}, s, dt, 10, 1000), 1000);
  // Already above the threshold, or within the margin of it: nothing is proven.
  EXPECT_EQ(holdsUntil({1.5, 0.0, 1e3, 0.0, 2.0}, s, dt, 10, 1000), 10);
  EXPECT_EQ(holdsUntil({1.0 - 1e-12, 0.0, 1e3, 0.0, 2.0}, s, dt, 10, 1000), 10);
  // F = 0.5 + 1e3 t along x reaches s at t = 5e-4 s, step 50000: proven up to a step before it.
  const std::int64_t until = holdsUntil({0.5, 0.0, 1e3, 0.0, 1.0}, s, dt, 0, std::int64_t(1) << 40);
  EXPECT_LE(until, 50000);
  EXPECT_GE(until, 49990);
  // Driven against the springs first: |F| falls to zero and grows again on the other side; the
  // block holds through the minimum until |F| = s again (t = 1.5e-3 s, step 150000).
  const std::int64_t back = holdsUntil({-0.5, 0.0, 1e3, 0.0, 1.0}, s, dt, 0, std::int64_t(1) << 40);
  EXPECT_LE(back, 150000);
  EXPECT_GE(back, 149990);
  // Rounding too large to prove anything against the margin: refuses.
  EXPECT_EQ(holdsUntil({0.5, 0.0, 1e3, 0.0, 1e8}, s, dt, 0, 1000), 0);
}
