// The counter-based stream: addressed draws, standard normal statistics.
#include "gradfric/core/random_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;

TEST(RandomStream, DrawsDependOnTheirAddressOnly) {
  const RandomStream a({7, 1, 2}), b({7, 1, 2});
  // Order of access does not matter.
  const auto late = a.normalPair(1000, 0, 0);
  const auto early = b.normalPair(3, 0, 0);
  EXPECT_EQ(late, b.normalPair(1000, 0, 0));
  EXPECT_EQ(early, a.normalPair(3, 0, 0));
  // Every part of the address changes the draw.
  EXPECT_NE(a.normalPair(3, 0, 0), a.normalPair(3, 0, 1));
  EXPECT_NE(a.normalPair(3, 0, 0), a.normalPair(3, 1, 0));
  EXPECT_NE(a.normalPair(3, 0, 0), RandomStream({8, 1, 2}).normalPair(3, 0, 0));
  EXPECT_NE(a.normalPair(3, 0, 0), RandomStream({7, 2, 2}).normalPair(3, 0, 0));
  EXPECT_NE(a.normalPair(3, 0, 0), RandomStream({7, 1, 3}).normalPair(3, 0, 0));
}

TEST(RandomStream, StandardNormalMoments) {
  const RandomStream s({1, 0, 0});
  const int n = 200000;
  double sum = 0, sum2 = 0, sum4 = 0, cross = 0;
  int beyondTwo = 0;
  for (int i = 0; i < n; ++i) {
    const auto [x, y] = s.normalPair(i, 0, 0);
    for (double z : {x, y}) {
      sum += z;
      sum2 += z * z;
      sum4 += z * z * z * z;
      beyondTwo += std::fabs(z) > 2;
    }
    cross += x * y;
  }
  const double m = 2.0 * n;
  EXPECT_NEAR(sum / m, 0.0, 5 / std::sqrt(m));
  EXPECT_NEAR(sum2 / m, 1.0, 5 * std::sqrt(2 / m));
  EXPECT_NEAR(sum4 / m, 3.0, 5 * std::sqrt(96 / m));
  EXPECT_NEAR(cross / n, 0.0, 5 / std::sqrt(double(n)));
  EXPECT_NEAR(beyondTwo / m, 0.0455, 0.003);  // P(|z| > 2)
}
