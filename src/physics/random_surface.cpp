#include "gradfric/physics/random_surface.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/random_stream.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gradfric {
namespace {

// RandomStream purposes: one per property and kind, so no two fields share a draw.
constexpr std::uint32_t kCellPurpose[3] = {0, 1, 2};
constexpr std::uint32_t kNodePurpose[3] = {3, 4, 5};

// Cells: edges quantised to multiples of 2^-32 l_c, within 2^20 l_c of the corner, so that
// u * 2^32 is an integer below 2^52 and every difference of two edges is exact.
constexpr double kQuantum = 0x1.0p-32;
constexpr double kLargestCoordinate = 0x1.0p20;  // in l_c
constexpr double kLargestPlate = 0x1.0p16;       // plate side in l_c

// Gaussian: grid spacing l_c / 4, kernel support |s| <= 2 l_c per axis (8 grid steps).
constexpr double kNodesPerLength = 4.0;
constexpr double kSupport = 2.0;  // in l_c

std::uint64_t packIndices(std::int64_t i, std::int64_t j) {
  return (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j);
}

void requireFinite(double value, bool ok, const std::string& what) {
  if (!std::isfinite(value) || !ok) throw std::invalid_argument("random surface: " + what);
}

double quantised(double u) { return std::nearbyint(u / kQuantum) * kQuantum; }

// value += a * b without rounding (fma gives the product's rounding error exactly).
void addExactProduct(ExactSum& sum, double a, double b) {
  const double product = a * b;
  const double error = std::fma(a, b, -product);
  sum.add(product);
  if (error != 0.0) sum.add(error);
}

// Sum of g(n/4)^2 over the truncated support at a node: the variance at the grid nodes is 1.
double kernelNormalisation() {
  double sum = 0.0;
  const int reach = static_cast<int>(kSupport * kNodesPerLength);
  for (int n = -reach; n <= reach; ++n) sum += std::exp(-4.0 * (n / kNodesPerLength) * (n / kNodesPerLength));
  return std::sqrt(sum);
}

// integral_a^b exp(-2 s^2) ds, with erfc where erf would cancel (both ends in one tail).
double gaussianIntegral(double a, double b) {
  const double scale = std::sqrt(M_PI / 8.0), root2 = std::sqrt(2.0);
  if (a >= 0.0) return scale * (std::erfc(root2 * a) - std::erfc(root2 * b));
  if (b <= 0.0) return scale * (std::erfc(-root2 * b) - std::erfc(-root2 * a));
  return scale * (std::erf(root2 * b) - std::erf(root2 * a));
}

// A block's weights on the grid nodes first..first+weight.size()-1 along one axis: the average
// of the truncated, normalised kernel over [u0, u1] (in l_c).
struct AxisWeights {
  std::int64_t first = 0;
  std::vector<double> weight;
};

AxisWeights axisWeights(double u0, double u1, double normalisation) {
  AxisWeights w;
  w.first = static_cast<std::int64_t>(std::ceil((u0 - kSupport) * kNodesPerLength));
  const auto last = static_cast<std::int64_t>(std::floor((u1 + kSupport) * kNodesPerLength));
  for (std::int64_t n = w.first; n <= last; ++n) {
    const double node = n / kNodesPerLength;
    const double a = std::max(u0 - node, -kSupport), b = std::min(u1 - node, kSupport);
    w.weight.push_back(a < b ? gaussianIntegral(a, b) / ((u1 - u0) * normalisation) : 0.0);
  }
  return w;
}

void checkEdges(const std::vector<double>& edges, double correlationLength, const char* axis) {
  if (edges.size() < 2) throw std::invalid_argument(std::string("random surface: fewer than two ") + axis + " edges");
  for (std::size_t e = 0; e < edges.size(); ++e) {
    requireFinite(edges[e], std::fabs(edges[e] / correlationLength) <= kLargestCoordinate,
                  std::string(axis) + " edge beyond 2^20 correlation lengths of the corner, or not finite");
    if (e > 0 && !(edges[e] > edges[e - 1]))
      throw std::invalid_argument(std::string("random surface: ") + axis + " edges not strictly increasing");
  }
}


// Adds the integral of the cell field over [u0, u1) x [v0, v1) (in cell units) to `integral`, cell by
// cell in increasing (i, j): each overlap area, exact in binary after quantisation, times the
// cell's values valuesOf(i, j) (one per property), through exact products.
template <class Values>
void integrateCells(double u0, double u1, double v0, double v1, int properties, Values&& valuesOf,
                    std::array<ExactSum, 3>& integral) {
  for (auto i = static_cast<std::int64_t>(std::floor(u0)); i < u1; ++i) {
    const double wx = std::min(u1, double(i + 1)) - std::max(u0, double(i));
    for (auto j = static_cast<std::int64_t>(std::floor(v0)); j < v1; ++j) {
      const double wy = std::min(v1, double(j + 1)) - std::max(v0, double(j));
      const double area = wx * wy, areaError = std::fma(wx, wy, -area);
      const double* z = valuesOf(i, j);
      for (int p = 0; p < properties; ++p) {
        addExactProduct(integral[p], z[p], area);
        if (areaError != 0.0) addExactProduct(integral[p], z[p], areaError);
      }
    }
  }
}

}  // namespace

std::string describeSurfaceField(const SurfaceSettings& s, double siteSpacing, const std::string& sites) {
  std::ostringstream d;
  d << "random surface: sigma_s = " << s.sigmaStatic << ", sigma_k = " << s.sigmaKinetic << ", "
    << surfaceKindName(s.kind) << " of l_c = " << formatReal(s.correlationLength) << " m ("
    << formatReal(s.correlationLength / siteSpacing) << " " << sites << ")";
  return d.str();
}

const char* surfaceKindName(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Cells: return "cells";
    case SurfaceKind::Gaussian: return "gaussian";
    case SurfaceKind::Blocks: return "blocks";
  }
  return "?";
}

RandomSurface::RandomSurface(const SurfaceSettings& s, double plateLength, std::uint32_t realisation,
                             std::uint32_t stream)
    : settings_(s), plateLength_(plateLength), realisation_(realisation), stream_(stream) {
  requireFinite(plateLength, plateLength > 0.0, "the plate length must be positive and finite");
  requireFinite(s.correlationLength, s.correlationLength > 0.0,
                "the correlation length must be positive and finite");
  requireFinite(s.sigmaStatic, s.sigmaStatic >= 0.0, "sigmaStatic must be >= 0 and finite");
  requireFinite(s.sigmaKinetic, s.sigmaKinetic >= 0.0, "sigmaKinetic must be >= 0 and finite");
  requireFinite(s.sigmaModulus, s.sigmaModulus >= 0.0, "sigmaModulus must be >= 0 and finite");
  if (!(plateLength / s.correlationLength <= kLargestPlate))
    throw std::invalid_argument("random surface: more than 2^16 correlation lengths per plate side");
  if (s.kind != SurfaceKind::Cells && s.kind != SurfaceKind::Gaussian)
    throw std::invalid_argument("random surface: the blocks kind is the lattice's own draw, not a field");
}

std::array<ExactSum, 3> RandomSurface::integralOver(const SurfaceRectangle& r) const {
  if (settings_.kind != SurfaceKind::Cells) throw std::logic_error("random surface: integralOver is for cells");
  checkEdges({r.x0, r.x1}, settings_.correlationLength, "x");
  checkEdges({r.y0, r.y1}, settings_.correlationLength, "y");
  const double u0 = quantised(r.x0 / settings_.correlationLength), u1 = quantised(r.x1 / settings_.correlationLength);
  const double v0 = quantised(r.y0 / settings_.correlationLength), v1 = quantised(r.y1 / settings_.correlationLength);
  const RandomStream stream({settings_.seed, stream_, realisation_});
  const int properties = settings_.sigmaModulus > 0.0 ? 3 : 2;
  std::array<ExactSum, 3> integral;
  double z[3] = {0, 0, 0};
  integrateCells(u0, u1, v0, v1, properties, [&](std::int64_t i, std::int64_t j) {
    for (int p = 0; p < properties; ++p) z[p] = stream.normalPair(packIndices(i, j), kCellPurpose[p], 0).first;
    return static_cast<const double*>(z);
  }, integral);
  return integral;
}

SurfaceDeviations RandomSurface::averageOver(const SurfaceRectangle& r) const {
  return averageOverLattice({r.x0, r.x1}, {r.y0, r.y1}).front();
}

std::vector<SurfaceDeviations> RandomSurface::averageOverLattice(const std::vector<double>& xEdges,
                                                                 const std::vector<double>& yEdges) const {
  const double lc = settings_.correlationLength;
  checkEdges(xEdges, lc, "x");
  checkEdges(yEdges, lc, "y");
  const std::size_t columns = xEdges.size() - 1, rows = yEdges.size() - 1;
  const int properties = settings_.sigmaModulus > 0.0 ? 3 : 2;
  const RandomStream stream({settings_.seed, stream_, realisation_});
  std::vector<SurfaceDeviations> out(columns * rows);
  auto component = [](SurfaceDeviations& d, int p) -> double& {
    return p == 0 ? d.zStatic : p == 1 ? d.zKinetic : d.zModulus;
  };

  if (settings_.kind == SurfaceKind::Cells) {
    std::vector<double> u(xEdges.size()), v(yEdges.size());
    for (std::size_t e = 0; e < u.size(); ++e) u[e] = quantised(xEdges[e] / lc);
    for (std::size_t e = 0; e < v.size(); ++e) v[e] = quantised(yEdges[e] / lc);
    // The cells under the lattice, drawn once: the same numbers integralOver draws one by one.
    const auto iFirst = static_cast<std::int64_t>(std::floor(u.front()));
    const auto jFirst = static_cast<std::int64_t>(std::floor(v.front()));
    const auto iCount = static_cast<std::size_t>(std::ceil(u.back()) - double(iFirst));
    const auto jCount = static_cast<std::size_t>(std::ceil(v.back()) - double(jFirst));
    std::vector<double> cell(iCount * jCount * properties);
    for (std::size_t i = 0; i < iCount; ++i)
      for (std::size_t j = 0; j < jCount; ++j)
        for (int p = 0; p < properties; ++p)
          cell[(i * jCount + j) * properties + p] =
              stream.normalPair(packIndices(iFirst + std::int64_t(i), jFirst + std::int64_t(j)), kCellPurpose[p], 0).first;
    for (std::size_t b = 0; b < rows; ++b)
      for (std::size_t a = 0; a < columns; ++a) {
        const double u0 = u[a], u1 = u[a + 1], v0 = v[b], v1 = v[b + 1];
        std::array<ExactSum, 3> integral;
        integrateCells(u0, u1, v0, v1, properties, [&](std::int64_t i, std::int64_t j) {
          return &cell[(std::size_t(i - iFirst) * jCount + std::size_t(j - jFirst)) * properties];
        }, integral);
        const double blockArea = (u1 - u0) * (v1 - v0);
        for (int p = 0; p < properties; ++p) component(out[b * columns + a], p) = integral[p].value() / blockArea;
      }
    return out;
  }

  // Gaussian: average = sum_{n,m} X_a(n) Y_b(m) xi(n, m), contracted over m first (per block row),
  // then over n (per block), each in increasing node order: the same operations whatever the
  // lattice, so a block gives the same bits alone or within any lattice.
  static const double normalisation = kernelNormalisation();
  std::vector<AxisWeights> xWeights(columns), yWeights(rows);
  for (std::size_t a = 0; a < columns; ++a) xWeights[a] = axisWeights(xEdges[a] / lc, xEdges[a + 1] / lc, normalisation);
  for (std::size_t b = 0; b < rows; ++b) yWeights[b] = axisWeights(yEdges[b] / lc, yEdges[b + 1] / lc, normalisation);
  std::int64_t nFirst = xWeights.front().first, nLast = nFirst, mFirst = yWeights.front().first, mLast = mFirst;
  for (const auto& w : xWeights) {
    nFirst = std::min(nFirst, w.first);
    nLast = std::max(nLast, w.first + std::int64_t(w.weight.size()) - 1);
  }
  for (const auto& w : yWeights) {
    mFirst = std::min(mFirst, w.first);
    mLast = std::max(mLast, w.first + std::int64_t(w.weight.size()) - 1);
  }
  const auto nCount = static_cast<std::size_t>(nLast - nFirst + 1), mCount = static_cast<std::size_t>(mLast - mFirst + 1);
  std::vector<double> noise(nCount * mCount), rowSum(rows * nCount);
  for (int p = 0; p < properties; ++p) {
    for (std::size_t n = 0; n < nCount; ++n)
      for (std::size_t m = 0; m < mCount; ++m)
        noise[n * mCount + m] =
            stream.normalPair(packIndices(nFirst + std::int64_t(n), mFirst + std::int64_t(m)), kNodePurpose[p], 0).first;
    for (std::size_t b = 0; b < rows; ++b) {
      const AxisWeights& y = yWeights[b];
      const std::size_t offset = std::size_t(y.first - mFirst);
      for (std::size_t n = 0; n < nCount; ++n) {
        const double* xi = &noise[n * mCount + offset];
        double sum = 0.0;
        for (std::size_t k = 0; k < y.weight.size(); ++k) sum += y.weight[k] * xi[k];
        rowSum[b * nCount + n] = sum;
      }
    }
    for (std::size_t b = 0; b < rows; ++b)
      for (std::size_t a = 0; a < columns; ++a) {
        const AxisWeights& x = xWeights[a];
        const double* row = &rowSum[b * nCount + std::size_t(x.first - nFirst)];
        double sum = 0.0;
        for (std::size_t k = 0; k < x.weight.size(); ++k) sum += x.weight[k] * row[k];
        component(out[b * columns + a], p) = sum;
      }
  }
  return out;
}

SurfaceDeviations RandomSurface::valueAt(double x, double y) const {
  const double lc = settings_.correlationLength;
  const double u = x / lc, v = y / lc;
  requireFinite(u, std::fabs(u) <= kLargestCoordinate, "point beyond 2^20 correlation lengths, or not finite");
  requireFinite(v, std::fabs(v) <= kLargestCoordinate, "point beyond 2^20 correlation lengths, or not finite");
  const int properties = settings_.sigmaModulus > 0.0 ? 3 : 2;
  const RandomStream stream({settings_.seed, stream_, realisation_});
  SurfaceDeviations d;
  double* z[3] = {&d.zStatic, &d.zKinetic, &d.zModulus};
  if (settings_.kind == SurfaceKind::Cells) {
    const auto i = static_cast<std::int64_t>(std::floor(quantised(u)));
    const auto j = static_cast<std::int64_t>(std::floor(quantised(v)));
    for (int p = 0; p < properties; ++p) *z[p] = stream.normalPair(packIndices(i, j), kCellPurpose[p], 0).first;
    return d;
  }
  static const double normalisation = kernelNormalisation();
  const auto nFirst = static_cast<std::int64_t>(std::ceil((u - kSupport) * kNodesPerLength));
  const auto mFirst = static_cast<std::int64_t>(std::ceil((v - kSupport) * kNodesPerLength));
  const auto reach = static_cast<std::int64_t>(2 * kSupport * kNodesPerLength);
  for (std::int64_t n = nFirst; n <= nFirst + reach; ++n) {
    const double sx = u - n / kNodesPerLength;
    if (std::fabs(sx) > kSupport) continue;
    for (std::int64_t m = mFirst; m <= mFirst + reach; ++m) {
      const double sy = v - m / kNodesPerLength;
      if (std::fabs(sy) > kSupport) continue;
      const double w = std::exp(-2.0 * (sx * sx + sy * sy)) / (normalisation * normalisation);
      for (int p = 0; p < properties; ++p) *z[p] += w * stream.normalPair(packIndices(n, m), kNodePurpose[p], 0).first;
    }
  }
  return d;
}

SurfaceCoefficients surfaceCoefficients(double meanStatic, double meanKinetic, double meanModulus,
                                        const SurfaceSettings& s, const SurfaceDeviations& z) {
  requireFinite(meanStatic, meanStatic > 0.0, "the mean static coefficient must be positive and finite");
  requireFinite(meanKinetic, meanKinetic > 0.0 && meanKinetic <= meanStatic,
                "the mean kinetic coefficient must be positive, finite and at most the static one");
  requireFinite(meanModulus, meanModulus > 0.0, "the mean modulus must be positive and finite");
  const double linearStatic = meanStatic * (1.0 + s.sigmaStatic * z.zStatic);
  const double linearKinetic = meanKinetic * (1.0 + s.sigmaKinetic * z.zKinetic);
  const double linearModulus = meanModulus * (1.0 + s.sigmaModulus * z.zModulus);
  SurfaceCoefficients c;
  c.muStatic = std::max(linearStatic, kSurfaceFloorFraction * meanStatic);
  c.muKinetic = std::min(std::max(linearKinetic, kSurfaceFloorFraction * meanKinetic), c.muStatic);
  c.youngsModulus = std::max(linearModulus, kSurfaceFloorFraction * meanModulus);
  c.clipped = c.muStatic != linearStatic || c.muKinetic != linearKinetic || c.youngsModulus != linearModulus;
  return c;
}

}  // namespace gradfric
