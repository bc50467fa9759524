#pragma once
// An exact sum of doubles. Every term is added without rounding into fixed-point digits that span
// the whole range of doubles, so the total does not depend on the order of the terms, nor on how
// they were split among ranks, and is rounded once when read. This is what keeps a parallel run's
// totals (the friction force, energies, the static solve's dot products) the same bits on any
// number of ranks: a sum of rounded partial sums changes in its last bits with the partition, and
// the sliding phase amplifies such a difference to percents (docs/fem.md, "Rank independence").
// PETSc-free; the reduction over ranks is core/reproducible_sum.hpp.
#include <array>
#include <cstdint>
#include <cstring>

namespace gradfric {

class ExactSum {
public:
  // 32-bit digits from 2^-1074 (the smallest subnormal) up to 2^1166: the largest double with
  // room for 2^142 of them. Stored in 64 bits so that 2^30 terms add without carrying.
  static constexpr int kDigits = 70;
  // The digits, then the counts of NaN, +inf and -inf terms (a non-finite term makes the total
  // non-finite, as in a plain sum).
  static constexpr int kWords = kDigits + 3;

  void add(double term) {  // inline: the hot loops add one term per node
    std::uint64_t bits = 0;
    std::memcpy(&bits, &term, sizeof bits);
    const std::uint64_t exponent = (bits >> 52) & 0x7ff;
    if (exponent - 1 >= 0x7fe) return addZeroSubnormalOrSpecial(bits);  // exponent 0 or 0x7ff
    // term = (2^52 + fraction) x 2^(exponent - 1075): its bits start at 2^-1074 x 2^(exponent - 1).
    const std::uint64_t mantissa = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
    addMagnitude(mantissa, static_cast<unsigned>(exponent - 1), bits >> 63);
  }
  ExactSum& operator+=(double term) {
    add(term);
    return *this;
  }
  ExactSum& operator+=(const ExactSum& other);
  // The exact total rounded to a double: within one unit in the last place of it, and a function
  // of the exact total only (the same bits whatever the order of the terms).
  double value() const;

  // For reductions (MPI_INT64_T, MPI_SUM over kWords words): digits carried into [0, 2^32) but
  // the top one, so that summing the words of 2^31 sums cannot overflow.
  void normalise();
  std::int64_t* words() { return word_.data(); }
  const std::int64_t* words() const { return word_.data(); }

private:
  void addZeroSubnormalOrSpecial(std::uint64_t bits);
  // mantissa x 2^position (in units of 2^-1074), negated if negative: three 32-bit pieces.
  void addMagnitude(std::uint64_t mantissa, unsigned position, std::uint64_t negative) {
    const unsigned digit = position >> 5, shift = position & 31;
    const std::uint64_t low = (mantissa << shift) & 0xffffffffu;
    const std::uint64_t high = mantissa >> (32 - shift);  // the bits from 2^32 up (shift 0: >> 32)
    const std::int64_t sign = -static_cast<std::int64_t>(negative);  // 0 or -1: x ^ sign - sign = +-x
    word_[digit] += (static_cast<std::int64_t>(low) ^ sign) - sign;
    word_[digit + 1] += (static_cast<std::int64_t>(high & 0xffffffffu) ^ sign) - sign;
    word_[digit + 2] += (static_cast<std::int64_t>(high >> 32) ^ sign) - sign;
    if (++pending_ == kCarryEvery) normalise();
  }
  static constexpr std::int64_t kCarryEvery = std::int64_t(1) << 30;

  std::array<std::int64_t, kWords> word_{};
  std::int64_t pending_ = 0;  // terms since the last carry
};

}  // namespace gradfric
