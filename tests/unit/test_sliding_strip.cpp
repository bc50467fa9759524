// The flutter simulated (physics/sliding_strip.hpp) against the dispersion relation
// (physics/sliding_dispersion.hpp): a periodic plane-strain strip sliding at constant friction, one
// wavelength seeded. Above mu = 1 the seeded wave grows at the relation's rate; at or below it does
// not. The window [2, 5] lambda/c_s starts once the seed's other waves have left the base and ends
// before the top's reflection (2 x 4 lambda of shear travel) returns.
#include "gradfric/physics/sliding_dispersion.hpp"
#include "gradfric/physics/sliding_strip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>
#include <cmath>

namespace gradfric {
namespace {

SlidingStripHistory strip(double mu, int elements) {
  SlidingStripSettings s;
  s.friction = mu;
  s.elementsPerWavelength = elements;
  s.depth = 4;
  s.duration = 6;
  return simulateSlidingStrip(s);
}

double largestAfter(const SlidingStripHistory& h, double from) {
  double largest = 0;
  for (std::size_t i = 0; i < h.time.size(); ++i)
    if (h.time[i] >= from) largest = std::max(largest, h.amplitude[i]);
  return largest;
}

TEST(SlidingStrip, AboveOneTheSeededWaveGrowsAtTheRateOfTheDispersionRelation) {
  for (double mu : {1.2, 1.4}) {
    const double predicted = slidingGrowthRate(mu, 1.0 / 3.0, 1.0, 1.0);  // [c_s / lambda]
    const double coarse = fittedGrowthRate(strip(mu, 16), 2, 5), fine = fittedGrowthRate(strip(mu, 32), 2, 5);
    EXPECT_NEAR(fine, predicted, 0.10 * predicted) << "mu " << mu;
    // The discretisation's part of the difference shrinks under refinement: the simulation
    // converges to the relation, not to a nearby value.
    EXPECT_LT(std::fabs(fine - predicted), std::fabs(coarse - predicted)) << "mu " << mu;
    // and it travels with the sliding at the root's speed, c_s Re(eta), a little below sqrt(2) c_s
    const double speed = fittedPhaseSpeed(strip(mu, 32), 2, 5);
    EXPECT_NEAR(speed, growingSlidingMode(mu, 1.0 / 3.0).eta.real(), 0.02) << "mu " << mu;
  }
}

TEST(SlidingStrip, AtOrBelowOneTheSeededWaveDoesNotGrow) {
  for (double mu : {0.0, 0.9, 1.0}) {
    const SlidingStripHistory h = strip(mu, 32);
    EXPECT_LT(largestAfter(h, 2), h.amplitude.front()) << "mu " << mu;  // below the seed from 2 lambda/c_s on
  }
  // and at 1.2 the same window ends well above the seed: e^(0.55 x 3) from 2 to 5
  const SlidingStripHistory h = strip(1.2, 32);
  EXPECT_GT(largestAfter(h, 5), 2 * h.amplitude.front());
}

TEST(SlidingStrip, BadSettingsAreRefused) {
  SlidingStripSettings s;
  s.poisson = 0.5;
  EXPECT_THROW(simulateSlidingStrip(s), std::invalid_argument);
  s = SlidingStripSettings{};
  s.courant = 1.5;
  EXPECT_THROW(simulateSlidingStrip(s), std::invalid_argument);
}

}  // namespace
}  // namespace gradfric

namespace gradfric {
namespace {

// With the normal-stress memory (docs/flutter.md, "With a normal-stress memory"): the relaxed
// reaction R*, dR*/dt = (R - R*) / T. At the seeded k = 2 pi / lambda, K = 2 pi T. Two waves
// grow at K < K_c: the flutter branch (with the sliding) and the memory's mode against it near
// -c_p; fittedWavePair separates them. The memory's mode is nearly a grazing P wave, so the strip
// is 8 lambda deep (its top's P reflection returns at t = 8) and the window is [2, 7].
SlidingStripHistory memoryStrip(double mu, double memoryK) {
  SlidingStripSettings s;
  s.friction = mu;
  s.elementsPerWavelength = 32;
  s.depth = 8;
  s.duration = 7;
  s.memory = memoryK / (2 * M_PI);
  return simulateSlidingStrip(s);
}

TEST(SlidingStrip, WithMemoryBelowTheCutoffBothBranchesGrowAtTheRelationsRates) {
  const double mu = 1.2, nu = 1.0 / 3.0, K = 0.5 * memoryCutoff(mu, nu);
  const std::vector<SlidingMode> modes = growingSlidingModes(mu, nu, K);
  ASSERT_EQ(modes.size(), 2u);
  const SlidingMode& against = modes[0].direction < 0 ? modes[0] : modes[1];
  const SlidingMode& flutter = modes[0].direction > 0 ? modes[0] : modes[1];
  const double rateFlutter = 2 * M_PI * flutter.eta.imag(), rateAgainst = 2 * M_PI * against.eta.imag();
  const SlidingStripHistory h = memoryStrip(mu, K);
  // The seeded wave as a whole: the faster root (the memory's mode, 0.379 against 0.276) dominates.
  EXPECT_NEAR(fittedGrowthRate(h, 2, 7), slidingGrowthRate(mu, nu, 1.0, 1.0, K / (2 * M_PI)), 0.10 * rateAgainst);
  EXPECT_NEAR(fittedPhaseSpeed(h, 2, 7), against.eta.real(), 0.02);
  // Each branch apart.
  const auto waves = fittedWavePair(h, 2, 7);
  EXPECT_NEAR(waves[0].growthRate, rateFlutter, 0.10 * rateFlutter);
  EXPECT_NEAR(waves[0].phaseSpeed, flutter.eta.real(), 0.02);
  EXPECT_NEAR(waves[1].growthRate, rateAgainst, 0.10 * rateAgainst);
  EXPECT_NEAR(waves[1].phaseSpeed, against.eta.real(), 0.02);
  // and slower than without the memory (0.552)
  EXPECT_LT(waves[0].growthRate, 0.8 * slidingGrowthRate(mu, nu, 1.0, 1.0));
}

TEST(SlidingStrip, WithMemoryAboveTheCutoffOnlyTheModeAgainstTheSlidingGrows) {
  const double mu = 1.2, nu = 1.0 / 3.0, K = 2 * memoryCutoff(mu, nu);
  const std::vector<SlidingMode> modes = growingSlidingModes(mu, nu, K);
  ASSERT_EQ(modes.size(), 1u);
  ASSERT_EQ(modes[0].direction, -1);
  const SlidingStripHistory h = memoryStrip(mu, K);
  // The amplitude stays below the seed over the window (the memory's mode, at 0.169 c_s/lambda,
  // starts from well below it) ...
  EXPECT_LT(largestAfter(h, 2), h.amplitude.front());
  const auto waves = fittedWavePair(h, 2, 7);
  // ... the wave with the sliding decays ...
  EXPECT_LT(waves[0].growthRate, 0.0);
  EXPECT_GT(waves[0].phaseSpeed, 0.5);
  // ... and what grows travels against it at the memory mode's speed. Its rate approaches the
  // relation's from below (0.148 over [2, 7]; 0.156 over [3, 7.5]): the root sits next to the
  // branch point -c_p/c_s, whose grazing P waves fade only slowly.
  EXPECT_NEAR(waves[1].phaseSpeed, modes[0].eta.real(), 0.02);
  EXPECT_GT(waves[1].growthRate, 0.75 * 2 * M_PI * modes[0].eta.imag());
  EXPECT_LT(waves[1].growthRate, 2 * M_PI * modes[0].eta.imag());
}

TEST(SlidingStrip, ZeroMemoryIsTheCoulombPathBitForBit) {
  SlidingStripSettings s;
  s.elementsPerWavelength = 8;
  s.duration = 2;
  const SlidingStripHistory a = simulateSlidingStrip(s);
  s.memory = 0;
  const SlidingStripHistory b = simulateSlidingStrip(s);
  EXPECT_EQ(a.amplitude, b.amplitude);
  s.memory = -1;
  EXPECT_THROW(simulateSlidingStrip(s), std::invalid_argument);
}

}  // namespace
}  // namespace gradfric
