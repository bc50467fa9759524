#include "gradfric/core/exact_sum.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace gradfric {

namespace {

constexpr int kNaN = ExactSum::kDigits, kPlusInf = ExactSum::kDigits + 1, kMinusInf = ExactSum::kDigits + 2;

}  // namespace

void ExactSum::addZeroSubnormalOrSpecial(std::uint64_t bits) {
  const std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
  if (((bits >> 52) & 0x7ff) == 0x7ff) {
    ++word_[mantissa ? kNaN : (bits >> 63) ? kMinusInf : kPlusInf];
    return;
  }
  if (mantissa != 0) addMagnitude(mantissa, 0, bits >> 63);  // a subnormal: mantissa x 2^-1074
}

ExactSum& ExactSum::operator+=(const ExactSum& other) {
  ExactSum carried = other;
  carried.normalise();
  normalise();
  for (int i = 0; i < kWords; ++i) word_[i] += carried.word_[i];
  return *this;
}

void ExactSum::normalise() {
  for (int i = 0; i + 1 < kDigits; ++i) {
    const std::int64_t carry = word_[i] >> 32;  // floor division by 2^32
    word_[i] -= carry * (std::int64_t(1) << 32);
    word_[i + 1] += carry;
  }
  pending_ = 0;
}

double ExactSum::value() const {
  if (word_[kNaN] > 0 || (word_[kPlusInf] > 0 && word_[kMinusInf] > 0))
    return std::numeric_limits<double>::quiet_NaN();
  if (word_[kPlusInf] > 0) return std::numeric_limits<double>::infinity();
  if (word_[kMinusInf] > 0) return -std::numeric_limits<double>::infinity();
  ExactSum s = *this;
  s.normalise();
  const bool negative = s.word_[kDigits - 1] < 0;
  if (negative) {  // the magnitude: negate every digit and carry again
    for (int i = 0; i < kDigits; ++i) s.word_[i] = -s.word_[i];
    s.normalise();
  }
  int top = kDigits - 1;
  while (top >= 0 && s.word_[top] == 0) --top;
  if (top < 0) return 0.0;
  // The top three digits (at least 65 significant bits) as one integer, rounded once to a double;
  // the digits below only decide ties, so the result is within one unit in the last place.
  const int low = top >= 2 ? top - 2 : 0;
  unsigned __int128 head = 0;
  for (int i = top; i >= low; --i) head = (head << 32) | static_cast<std::uint64_t>(s.word_[i]);
  const double magnitude = std::ldexp(static_cast<double>(head), 32 * low - 1074);
  return negative ? -magnitude : magnitude;
}

}  // namespace gradfric
