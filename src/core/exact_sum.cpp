#include "gradfric/core/exact_sum.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace gradfric {

namespace {

constexpr int kNaN = ExactSum::kDigits, kPlusInf = ExactSum::kDigits + 1, kMinusInf = ExactSum::kDigits + 2;
constexpr std::int64_t kCarryEvery = std::int64_t(1) << 30;

}  // namespace

void ExactSum::add(double term) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &term, sizeof bits);
  const bool negative = bits >> 63;
  const int exponent = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
  if (exponent == 0x7ff) {
    ++word_[mantissa ? kNaN : negative ? kMinusInf : kPlusInf];
    return;
  }
  if (exponent == 0 && mantissa == 0) return;
  // term = mantissa x 2^(exponent - 1075) = mantissa x 2^-1074 x 2^position (subnormals: exponent 1).
  int position = exponent - 1;
  if (exponent == 0) position = 0;
  else mantissa |= std::uint64_t(1) << 52;
  const int digit = position >> 5;
  const unsigned __int128 shifted = static_cast<unsigned __int128>(mantissa) << (position & 31);  // < 2^85
  const std::int64_t parts[3] = {static_cast<std::int64_t>(shifted & 0xffffffffu),
                                 static_cast<std::int64_t>((shifted >> 32) & 0xffffffffu),
                                 static_cast<std::int64_t>(shifted >> 64)};
  for (int i = 0; i < 3; ++i) word_[digit + i] += negative ? -parts[i] : parts[i];
  if (++pending_ == kCarryEvery) normalise();
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
