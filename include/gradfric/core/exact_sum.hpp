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

namespace gradfric {

class ExactSum {
public:
  // 32-bit digits from 2^-1074 (the smallest subnormal) up to 2^1166: the largest double with
  // room for 2^142 of them. Stored in 64 bits so that 2^30 terms add without carrying.
  static constexpr int kDigits = 70;
  // The digits, then the counts of NaN, +inf and -inf terms (a non-finite term makes the total
  // non-finite, as in a plain sum).
  static constexpr int kWords = kDigits + 3;

  void add(double term);
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
  std::array<std::int64_t, kWords> word_{};
  std::int64_t pending_ = 0;  // terms since the last carry
};

}  // namespace gradfric
