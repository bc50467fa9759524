// The exact sum (core/exact_sum.hpp): the same bits in any order and any split, and within one
// unit in the last place of the correctly rounded total, which Shewchuk's error-free partials
// (the algorithm of Python's math.fsum) compute independently here.
#include "gradfric/core/exact_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using gradfric::ExactSum;

// Shewchuk's msum: non-overlapping partials whose exact sum is the exact sum of the terms.
double shewchukSum(const std::vector<double>& terms) {
  std::vector<double> partials;
  for (double x : terms) {
    std::size_t i = 0;
    for (double y : partials) {
      if (std::fabs(x) < std::fabs(y)) std::swap(x, y);
      const double hi = x + y, lo = y - (hi - x);
      if (lo != 0.0) partials[i++] = lo;
      x = hi;
    }
    partials.resize(i);
    partials.push_back(x);
  }
  double total = 0;
  for (auto it = partials.rbegin(); it != partials.rend(); ++it) total += *it;
  return total;
}

double exactSum(const std::vector<double>& terms) {
  ExactSum s;
  for (double t : terms) s.add(t);
  return s.value();
}

std::uint64_t bitsOf(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

std::vector<double> wideTerms(unsigned seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<double> terms(n);
  for (double& t : terms) t = std::ldexp(mantissa(rng), exponent(rng));
  return terms;
}

}  // namespace

TEST(ExactSum, SameBitsInAnyOrderAndAnySplit) {
  std::vector<double> terms = wideTerms(7, 20000);
  const double reference = exactSum(terms);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(terms.begin(), terms.end(), rng);
    EXPECT_EQ(bitsOf(exactSum(terms)), bitsOf(reference));
    // Split into uneven pieces summed apart, then merged: what ranks do.
    ExactSum merged;
    std::size_t start = 0;
    for (std::size_t piece : {1u, 999u, 7000u, 12000u}) {
      ExactSum part;
      for (std::size_t i = start; i < std::min(terms.size(), start + piece); ++i) part.add(terms[i]);
      merged += part;
      start += piece;
    }
    EXPECT_EQ(bitsOf(merged.value()), bitsOf(reference));
  }
  double plain = 0;  // the control: a plain sum does change with the order
  for (double t : terms) plain += t;
  std::reverse(terms.begin(), terms.end());
  double reversed = 0;
  for (double t : terms) reversed += t;
  EXPECT_NE(bitsOf(plain), bitsOf(reversed));
}

TEST(ExactSum, WithinOneUlpOfTheCorrectlyRoundedTotal) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const std::vector<double> terms = wideTerms(seed, 2000);
    const double exact = shewchukSum(terms), ours = exactSum(terms);
    EXPECT_LE(std::fabs(ours - exact), std::fabs(std::nextafter(exact, 2 * exact + 1) - exact)) << "seed " << seed;
  }
}

TEST(ExactSum, CancellationAndTheEdgesOfTheRange) {
  EXPECT_EQ(exactSum({1e308, 1.0, -1e308}), 1.0);                     // a plain sum gives 0
  EXPECT_EQ(exactSum({1e16, 1.0, 1.0, -1e16}), 2.0);
  EXPECT_EQ(exactSum({4.9e-324, 4.9e-324, -4.9e-324}), 4.9e-324);   // subnormals
  EXPECT_EQ(exactSum({-2.5, 0.5}), -2.0);
  EXPECT_EQ(exactSum({}), 0.0);
  EXPECT_EQ(exactSum({0.1, 0.2}), 0.1 + 0.2);                        // one rounding, as a plain sum
  std::vector<double> tenths(10, 0.1);
  EXPECT_EQ(exactSum(tenths), 1.0);  // the correctly rounded sum; a plain sum gives 0.9999999999999999
  EXPECT_TRUE(std::isinf(exactSum({1e308, 1e308})));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(exactSum({1.0, inf}), inf);
  EXPECT_EQ(exactSum({1.0, -inf}), -inf);
  EXPECT_TRUE(std::isnan(exactSum({inf, -inf})));
  EXPECT_TRUE(std::isnan(exactSum({1.0, std::numeric_limits<double>::quiet_NaN()})));
}

TEST(ExactSum, ManyTermsCarryWithoutOverflow) {
  ExactSum s;  // more terms than one carry period would allow without carrying
  const long n = (1L << 30) + 12345;
  for (long i = 0; i < n; ++i) s.add(std::ldexp(1.0, 20) - 1.0);  // 2^20 - 1: all 32-bit digit bits busy
  EXPECT_EQ(s.value(), static_cast<double>(n) * (std::ldexp(1.0, 20) - 1.0));
}
