// The flutter simulated (physics/sliding_strip.hpp) against the dispersion relation
// (physics/sliding_dispersion.hpp): a periodic plane-strain strip sliding at constant friction, one
// wavelength seeded. Above mu = 1 the seeded wave grows at the relation's rate; at or below it does
// not. The window [2, 5] lambda/c_s starts once the seed's other waves have left the base and ends
// before the top's reflection (2 x 4 lambda of shear travel) returns.
#include "gradfric/physics/sliding_dispersion.hpp"
#include "gradfric/physics/sliding_strip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
