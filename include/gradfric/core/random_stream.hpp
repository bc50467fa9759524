#pragma once
// Counter-based random numbers (Random123 Philox4x64-10): a draw is addressed by
// (seed, stream, item, purpose, attempt), never by the order of draws, so a realisation gives the
// same numbers whichever rank runs it and in whatever order tasks finish.
#include <Random123/philox.h>

#include <cmath>
#include <cstdint>
#include <utility>

namespace gradfric {

struct StreamKey {
  std::uint64_t seed = 0;
  std::uint32_t sweepIndex = 0;   // which sweep point
  std::uint32_t realisation = 0;  // which realisation of that point
};

class RandomStream {
public:
  explicit RandomStream(StreamKey key) {
    key_ = {{key.seed, (std::uint64_t(key.sweepIndex) << 32) | key.realisation}};
  }
  // Two independent standard normal deviates for (item, purpose, attempt), by Box-Muller.
  std::pair<double, double> normalPair(std::uint64_t item, std::uint32_t purpose, std::uint32_t attempt) const {
    r123::Philox4x64 generator;
    r123::Philox4x64::ctr_type counter = {{item, (std::uint64_t(purpose) << 32) | attempt, 0, 0}};
    const auto bits = generator(counter, key_);
    const double u1 = toOpenUnit(bits.v[0]);
    const double u2 = toOpenUnit(bits.v[1]);
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * M_PI * u2;
    return {radius * std::cos(angle), radius * std::sin(angle)};
  }

private:
  // (0, 1]: the top 53 bits, shifted by one so that log() never sees zero.
  static double toOpenUnit(std::uint64_t bits) { return (double((bits >> 11) + 1)) * 0x1.0p-53; }
  r123::Philox4x64::key_type key_;
};

}  // namespace gradfric
