// The random surface (physics/random_surface.hpp): field statistics against its covariance, exact
// block averages across lattices, independence of lattice, order and rank, the coefficient rule
// and the refusals. Bounds are 5 standard errors from the number of independent correlation
// areas n_c of the sampled region (cells: one per cell; Gaussian: area / (pi l_c^2), the integral
// of its covariance): a false failure has probability below 1e-6 for each check.
#include "gradfric/physics/random_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace gradfric;

namespace {

constexpr double kPlate = 0.12;  // L [m]; l_c = L / 120 = 1 mm, not a power of two

SurfaceSettings settings(SurfaceKind kind, std::uint64_t seed = 11) {
  SurfaceSettings s;
  s.sigmaStatic = 0.1;
  s.sigmaKinetic = 0.05;
  s.correlationLength = defaultCorrelationLength(kPlate);
  s.kind = kind;
  s.seed = seed;
  return s;
}

// Edges of a lattice of n blocks over [0, extent], computed as a model would: extent c / n.
std::vector<double> edges(double extent, int n) {
  std::vector<double> e(n + 1);
  for (int c = 0; c <= n; ++c) e[c] = extent * c / n;
  return e;
}

double zStatic(const SurfaceDeviations& d) { return d.zStatic; }

// Statistics of z_s over an n x n lattice (row-major): mean, variance, and the correlation at lags
// 0..maxLag blocks along x and y together.
struct FieldStatistics {
  double mean = 0, variance = 0;
  std::vector<double> correlation;
};
FieldStatistics statistics(const std::vector<SurfaceDeviations>& z, int n, int maxLag) {
  FieldStatistics s;
  for (const auto& d : z) s.mean += zStatic(d);
  s.mean /= z.size();
  for (const auto& d : z) s.variance += (zStatic(d) - s.mean) * (zStatic(d) - s.mean);
  s.variance /= z.size();
  for (int lag = 0; lag <= maxLag; ++lag) {
    double sum = 0;
    long pairs = 0;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c + lag < n; ++c) {
        sum += (zStatic(z[r * n + c]) - s.mean) * (zStatic(z[r * n + c + lag]) - s.mean);
        sum += (zStatic(z[c * n + r]) - s.mean) * (zStatic(z[(c + lag) * n + r]) - s.mean);
        pairs += 2;
      }
    s.correlation.push_back(sum / pairs / s.variance);
  }
  return s;
}

// The lag (in blocks) where a correlation sampled at whole lags first falls to 1/e, linearly
// interpolated.
double lagOfOneOverE(const std::vector<double>& correlation) {
  const double target = std::exp(-1.0);
  for (std::size_t k = 1; k < correlation.size(); ++k)
    if (correlation[k] <= target)
      return (k - 1) + (correlation[k - 1] - target) / (correlation[k - 1] - correlation[k]);
  return -1;
}

// Gaussian covariance exp(-r^2) (r in l_c): the 1D covariance of averages over segments of length
// t at lag r, times t^2: G(r) = F(r + t) + F(r - t) - 2 F(r), F(s) = sqrt(pi)/2 s erf(s) + e^{-s^2}/2.
double segmentCovariance(double r, double t) {
  auto F = [](double s) { return 0.5 * std::sqrt(M_PI) * s * std::erf(s) + 0.5 * std::exp(-s * s); };
  return F(r + t) + F(r - t) - 2.0 * F(r);
}

}  // namespace

TEST(RandomSurface, CellFieldHasUnitVarianceAndTheCellsCorrelation) {
  // Blocks of l_c / 4 over 128 x 128 cells: each block is a cell's value; the correlation at lag r
  // along an axis is the chance of sharing a cell, max(0, 1 - r / l_c), 1/e at r = (1 - 1/e) l_c.
  const SurfaceSettings s = settings(SurfaceKind::Cells);
  const RandomSurface surface(s, kPlate, 0);
  const int cells = 128, n = 4 * cells;
  const double extent = cells * s.correlationLength;
  const auto z = surface.averageOverLattice(edges(extent, n), edges(extent, n));
  const double nc = double(cells) * cells, bound = 5.0 * std::sqrt(2.0 / nc);
  const FieldStatistics st = statistics(z, n, 8);
  EXPECT_NEAR(st.mean, 0.0, 5.0 / std::sqrt(nc));
  EXPECT_NEAR(st.variance, 1.0, bound);
  for (int lag = 0; lag <= 8; ++lag) EXPECT_NEAR(st.correlation[lag], std::max(0.0, 1.0 - lag / 4.0), bound) << lag;
  EXPECT_NEAR(lagOfOneOverE(st.correlation) / 4.0, 1.0 - std::exp(-1.0), bound);  // slope 1 per l_c
  // A block inside a cell is that cell's value, bit for bit.
  EXPECT_EQ(z[5 * n + 7], surface.valueAt(7.5 * extent / n, 5.5 * extent / n));
}

TEST(RandomSurface, GaussianFieldHasUnitVarianceAndGaussianCorrelation) {
  // Blocks of l_c / 4 over 256 x 256 l_c: nearly points; the theory is the block-averaged
  // covariance G(r) / G(0) (variance (G(0) / t^2)^2 = 0.980 for t = 1/4); its 1/e lag, interpolated between
  // lags of l_c / 4 as the samples are, is 1.012 l_c.
  const SurfaceSettings s = settings(SurfaceKind::Gaussian);
  const RandomSurface surface(s, kPlate, 0);
  const int lengths = 256, n = 4 * lengths;
  const double extent = lengths * s.correlationLength, t = 0.25;
  const auto z = surface.averageOverLattice(edges(extent, n), edges(extent, n));
  const double nc = double(lengths) * lengths / M_PI, bound = 5.0 * std::sqrt(2.0 / nc);
  const FieldStatistics st = statistics(z, n, 8);
  const double blockVariance = std::pow(segmentCovariance(0, t) / (t * t), 2);
  EXPECT_NEAR(st.mean, 0.0, 5.0 / std::sqrt(nc));
  EXPECT_NEAR(st.variance, blockVariance, bound);
  std::vector<double> theory;
  for (int lag = 0; lag <= 8; ++lag) {
    theory.push_back(segmentCovariance(lag * t, t) / segmentCovariance(0, t));
    EXPECT_NEAR(st.correlation[lag], theory.back(), bound) << lag;
  }
  // The 1/e lag: a correlation error e moves it by e / |slope|, slope 2/e at r = l_c.
  EXPECT_NEAR(lagOfOneOverE(st.correlation) * t, lagOfOneOverE(theory) * t, bound / (2.0 * std::exp(-1.0)));
  EXPECT_NEAR(lagOfOneOverE(theory) * t, 1.0, 0.02);  // averaging and interpolation: +1.2 %
  // A tiny block's exact average is the point value (the erf integrals and the kernel agree).
  const double x = 0.0123, y = 0.0456, h = 1e-4 * s.correlationLength;
  const auto point = surface.valueAt(x, y);
  const auto tiny = surface.averageOver({x - h, x + h, y - h, y + h});
  EXPECT_NEAR(tiny.zStatic, point.zStatic, 1e-7);
  EXPECT_NEAR(tiny.zKinetic, point.zKinetic, 1e-7);
}

TEST(RandomSurface, CoarseCellBlockIsTheMeanOfItsFineBlocksBitwise) {
  const SurfaceSettings s = settings(SurfaceKind::Cells);
  const RandomSurface surface(s, kPlate, 3);
  for (int coarseN : {60, 120}) {  // fine blocks of one cell, then of half a cell
    const auto coarse = surface.averageOverLattice(edges(kPlate, coarseN), edges(kPlate, coarseN));
    const auto fine = surface.averageOverLattice(edges(kPlate, 2 * coarseN), edges(kPlate, 2 * coarseN));
    int differing = 0;
    for (int b = 0; b < coarseN; ++b)
      for (int a = 0; a < coarseN; ++a) {
        ExactSum sumS, sumK;
        for (int k = 0; k < 4; ++k) {
          const auto& f = fine[(2 * b + k / 2) * 2 * coarseN + 2 * a + k % 2];
          sumS += f.zStatic;
          sumK += f.zKinetic;
        }
        const auto& c = coarse[b * coarseN + a];
        differing += c.zStatic != sumS.value() / 4 || c.zKinetic != sumK.value() / 4;
      }
    EXPECT_EQ(differing, 0) << coarseN;
  }
  // Blocks of several cells: the exact integrals add up bit for bit (4 x 4 cells = sum of four
  // blocks of 2 x 2 cells), which the rounded averages cannot promise.
  const auto fineEdges = edges(kPlate, 60);
  const auto coarseEdges = edges(kPlate, 30);
  int differing = 0;
  for (int b = 0; b < 30; b += 7)
    for (int a = 0; a < 30; a += 5) {
      const auto whole = surface.integralOver({coarseEdges[a], coarseEdges[a + 1], coarseEdges[b], coarseEdges[b + 1]});
      std::array<ExactSum, 3> parts;
      for (int k = 0; k < 4; ++k) {
        const int fa = 2 * a + k % 2, fb = 2 * b + k / 2;
        const auto part = surface.integralOver({fineEdges[fa], fineEdges[fa + 1], fineEdges[fb], fineEdges[fb + 1]});
        for (int p = 0; p < 2; ++p) parts[p] += part[p];
      }
      for (int p = 0; p < 2; ++p) differing += whole[p].value() != parts[p].value();
    }
  EXPECT_EQ(differing, 0);
}

TEST(RandomSurface, CoarseGaussianBlockIsTheMeanOfItsFineBlocksToRoundOff) {
  // Each average is a sum of about 500 products of O(1) weights and |xi| < 6: its rounding is a
  // few 1e-15; 1e-12 leaves room and still catches any error in the integrals (O(1e-3) or more).
  const RandomSurface surface(settings(SurfaceKind::Gaussian), kPlate, 3);
  const auto coarse = surface.averageOverLattice(edges(kPlate, 60), edges(kPlate, 60));
  const auto fine = surface.averageOverLattice(edges(kPlate, 120), edges(kPlate, 120));
  double largest = 0;
  for (int b = 0; b < 60; ++b)
    for (int a = 0; a < 60; ++a) {
      double mean = 0;
      for (int k = 0; k < 4; ++k) mean += fine[(2 * b + k / 2) * 120 + 2 * a + k % 2].zStatic / 4;
      largest = std::max(largest, std::fabs(coarse[b * 60 + a].zStatic - mean));
    }
  EXPECT_LT(largest, 1e-12);
}

TEST(RandomSurface, CellBlocksOfTwoCellsHaveVarianceOneQuarter) {
  const SurfaceSettings s = settings(SurfaceKind::Cells, 5);
  const RandomSurface surface(s, kPlate, 1);
  const int n = 200;  // independent blocks of 2 x 2 cells
  const double extent = 2 * n * s.correlationLength;
  const auto z = surface.averageOverLattice(edges(extent, n), edges(extent, n));
  const FieldStatistics st = statistics(z, n, 0);
  EXPECT_NEAR(st.mean, 0.0, 5.0 * 0.5 / n);
  EXPECT_NEAR(st.variance, 0.25, 5.0 * 0.25 * std::sqrt(2.0) / n);
}

TEST(RandomSurface, GaussianSquareAveragesHaveTheClosedFormVariance) {
  // The variance of the average over a square of side t l_c is (G(0) / t^2)^2: 0.4053 at t = 2.
  // Relative standard error of the sample variance: sqrt(2 pi / (area var)), area in l_c^2.
  const SurfaceSettings s = settings(SurfaceKind::Gaussian, 5);
  const RandomSurface surface(s, kPlate, 1);
  const int n = 128;
  const double t = 2.0, extent = n * t * s.correlationLength, area = std::pow(n * t, 2);
  const auto z = surface.averageOverLattice(edges(extent, n), edges(extent, n));
  const FieldStatistics st = statistics(z, n, 0);
  const double theory = std::pow(segmentCovariance(0, t) / (t * t), 2);
  EXPECT_NEAR(theory, 0.4053, 1e-4);
  EXPECT_NEAR(st.mean, 0.0, 5.0 * std::sqrt(M_PI / area));
  EXPECT_NEAR(st.variance, theory, 5.0 * theory * std::sqrt(2.0 * M_PI / (area * theory)));
}

TEST(RandomSurface, SameBitsOnAnyLatticeInAnyOrder) {
  for (SurfaceKind kind : {SurfaceKind::Cells, SurfaceKind::Gaussian}) {
    SurfaceSettings s = settings(kind);
    s.sigmaModulus = 0.2;
    const RandomSurface surface(s, kPlate, 7);
    const RandomSurface otherPlate(s, 0.3, 7);  // built for another plate (and lattice)
    const auto xEdges = edges(kPlate, 37), yEdges = edges(kPlate, 41);
    const auto whole = surface.averageOverLattice(xEdges, yEdges);
    int differing = 0;
    for (int b = 40; b >= 0; b -= 3)  // single blocks, backwards
      for (int a = 36; a >= 0; a -= 2)
        differing += !(otherPlate.averageOver({xEdges[a], xEdges[a + 1], yEdges[b], yEdges[b + 1]}) == whole[b * 37 + a]);
    // A sub-lattice, as a rank owning part of the plate would ask.
    const std::vector<double> xPart(xEdges.begin() + 10, xEdges.begin() + 20), yPart(yEdges.begin() + 3, yEdges.begin() + 9);
    const auto part = otherPlate.averageOverLattice(xPart, yPart);
    for (int b = 0; b < 5; ++b)
      for (int a = 0; a < 9; ++a) differing += !(part[b * 9 + a] == whole[(b + 3) * 37 + a + 10]);
    EXPECT_EQ(differing, 0);
    // Another realisation or seed is another surface.
    SurfaceSettings reseeded = s;
    reseeded.seed = s.seed + 1;
    const auto otherRealisation = RandomSurface(s, kPlate, 8).averageOverLattice(xEdges, yEdges);
    const auto otherSeed = RandomSurface(reseeded, kPlate, 7).averageOverLattice(xEdges, yEdges);
    int equal = 0;
    for (std::size_t i = 0; i < whole.size(); ++i)
      equal += whole[i].zStatic == otherRealisation[i].zStatic || whole[i].zStatic == otherSeed[i].zStatic ||
               whole[i].zModulus == otherSeed[i].zModulus;
    EXPECT_EQ(equal, 0);
  }
}

TEST(RandomSurface, PropertiesAreUncorrelatedAndModulusOnlyWhenAsked) {
  for (SurfaceKind kind : {SurfaceKind::Cells, SurfaceKind::Gaussian}) {
    SurfaceSettings s = settings(kind, 21);
    s.sigmaModulus = 0.1;
    const RandomSurface surface(s, kPlate, 0);
    const int n = 200;
    const double extent = n * s.correlationLength;
    const auto z = surface.averageOverLattice(edges(extent, n), edges(extent, n));
    // Cells: n^2 independent values; Gaussian: n^2 / pi correlation areas.
    const double nc = kind == SurfaceKind::Cells ? double(n) * n : double(n) * n / M_PI;
    double sk = 0, se = 0, ss = 0, kk = 0, ee = 0;
    for (const auto& d : z) {
      sk += d.zStatic * d.zKinetic;
      se += d.zStatic * d.zModulus;
      ss += d.zStatic * d.zStatic;
      kk += d.zKinetic * d.zKinetic;
      ee += d.zModulus * d.zModulus;
    }
    EXPECT_NEAR(sk / std::sqrt(ss * kk), 0.0, 5.0 / std::sqrt(nc));
    EXPECT_NEAR(se / std::sqrt(ss * ee), 0.0, 5.0 / std::sqrt(nc));
    // Without modulus disorder z_E is zero and z_s, z_k are unchanged.
    s.sigmaModulus = 0.0;
    const auto noModulus = RandomSurface(s, kPlate, 0).averageOver({0.0, extent / n, 0.0, extent / n});
    EXPECT_EQ(noModulus.zModulus, 0.0);
    EXPECT_EQ(noModulus.zStatic, z[0].zStatic);
    EXPECT_EQ(noModulus.zKinetic, z[0].zKinetic);
  }
}

TEST(RandomSurface, CoefficientsKeepKineticBelowStaticAndPositive) {
  SurfaceSettings s = settings(SurfaceKind::Cells);
  s.sigmaStatic = 3.0;
  s.sigmaKinetic = 3.0;
  s.sigmaModulus = 3.0;
  for (double zs = -6; zs <= 6; zs += 0.25)
    for (double zk = -6; zk <= 6; zk += 0.25) {
      const auto c = surfaceCoefficients(1.0, 0.6, 1e7, s, {zs, zk, zk});
      EXPECT_GT(c.muKinetic, 0.0);
      EXPECT_LE(c.muKinetic, c.muStatic);
      EXPECT_GE(c.muStatic, kSurfaceFloorFraction * 1.0);
      EXPECT_GE(c.youngsModulus, kSurfaceFloorFraction * 1e7);
      // Reported as clipped exactly when a bound replaced the linear value.
      const bool floorOrCap = 1.0 + 3.0 * zs < kSurfaceFloorFraction || 1.0 + 3.0 * zk < kSurfaceFloorFraction ||
                              0.6 * (1.0 + 3.0 * zk) > c.muStatic;
      EXPECT_EQ(c.clipped, floorOrCap) << zs << " " << zk;
    }
  // Away from the floor and the cap the rule is the linear map.
  const auto linear = surfaceCoefficients(1.0, 0.6, 1e7, s, {0.1, -0.05, 0.2});
  EXPECT_DOUBLE_EQ(linear.muStatic, 1.3);
  EXPECT_DOUBLE_EQ(linear.muKinetic, 0.6 * 0.85);
  EXPECT_DOUBLE_EQ(linear.youngsModulus, 1.6e7);
  EXPECT_FALSE(linear.clipped);
  // Zero dispersion: the means, whatever the deviations.
  const SurfaceSettings none = settings(SurfaceKind::Gaussian);
  SurfaceSettings zero = none;
  zero.sigmaStatic = zero.sigmaKinetic = zero.sigmaModulus = 0.0;
  for (double z : {-5.0, 0.0, 3.0}) {
    const auto c = surfaceCoefficients(1.0, 0.6, 1e7, zero, {z, -z, z});
    EXPECT_EQ(c.muStatic, 1.0);
    EXPECT_EQ(c.muKinetic, 0.6);
    EXPECT_EQ(c.youngsModulus, 1e7);
  }
}

TEST(RandomSurface, RefusesBadSettingsAndRegions) {
  const double nan = std::nan(""), inf = INFINITY;
  auto refused = [](SurfaceSettings s, double plate = kPlate) {
    try {
      RandomSurface(s, plate, 0);
    } catch (const std::invalid_argument&) {
      return true;
    }
    return false;
  };
  const SurfaceSettings good = settings(SurfaceKind::Cells);
  EXPECT_FALSE(refused(good));
  for (double lc : {0.0, -1e-3, nan, inf, kPlate / 70000}) {
    SurfaceSettings s = good;
    s.correlationLength = lc;
    EXPECT_TRUE(refused(s)) << lc;
  }
  for (double sigma : {-0.1, nan, inf}) {
    SurfaceSettings s = good;
    s.sigmaStatic = sigma;
    EXPECT_TRUE(refused(s)) << sigma;
    s = good;
    s.sigmaKinetic = sigma;
    EXPECT_TRUE(refused(s)) << sigma;
    s = good;
    s.sigmaModulus = sigma;
    EXPECT_TRUE(refused(s)) << sigma;
  }
  for (double plate : {0.0, -1.0, nan, inf}) EXPECT_TRUE(refused(good, plate)) << plate;
  SurfaceSettings unknown = good;
  unknown.kind = static_cast<SurfaceKind>(7);
  EXPECT_TRUE(refused(unknown));

  for (SurfaceKind kind : {SurfaceKind::Cells, SurfaceKind::Gaussian}) {
    const RandomSurface surface(settings(kind), kPlate, 0);
    EXPECT_THROW(surface.averageOver({0.01, 0.01, 0.0, 0.01}), std::invalid_argument);  // empty
    EXPECT_THROW(surface.averageOver({0.02, 0.01, 0.0, 0.01}), std::invalid_argument);  // reversed
    EXPECT_THROW(surface.averageOver({0.0, nan, 0.0, 0.01}), std::invalid_argument);
    EXPECT_THROW(surface.averageOver({0.0, 0.01, 0.0, 1e4}), std::invalid_argument);  // 1e7 l_c away
    EXPECT_THROW(surface.averageOverLattice({0.0}, {0.0, 0.01}), std::invalid_argument);
    EXPECT_THROW(surface.averageOverLattice({0.0, 0.02, 0.01}, {0.0, 0.01}), std::invalid_argument);
    EXPECT_THROW(surface.valueAt(inf, 0.0), std::invalid_argument);
  }
  EXPECT_THROW(RandomSurface(settings(SurfaceKind::Gaussian), kPlate, 0).integralOver({0, 0.01, 0, 0.01}),
               std::logic_error);
  const SurfaceSettings s = settings(SurfaceKind::Cells);
  EXPECT_THROW(surfaceCoefficients(0.0, 0.0, 1e7, s, {}), std::invalid_argument);
  EXPECT_THROW(surfaceCoefficients(0.5, 0.6, 1e7, s, {}), std::invalid_argument);  // mu_k > mu_s
  EXPECT_THROW(surfaceCoefficients(1.0, 0.6, nan, s, {}), std::invalid_argument);
}
