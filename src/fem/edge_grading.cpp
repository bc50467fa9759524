#include "gradfric/fem/edge_grading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gradfric::fem {

namespace {

// Sizes (interior size 1) at the outer and inner end of refined band k (0 at the edge):
// geometric across the refined bands, from 1/ratio at the edge to 1 at the interior.
double bandEndSize(double ratio, int bands, int k) { return std::pow(ratio, double(k) / bands - 1.0); }

constexpr int kLargestUnit = 4096;  // interior cells per band per unit tried before giving up

}  // namespace

EdgeMap::EdgeMap(double ratio, int refinedBands) : ratio_(ratio), refinedBands_(refinedBands) {
  if (uniform()) {
    bandCells_.assign(kGradingBands, 0);
    return;
  }
  if (!(ratio >= kEdgeRatioMin && ratio <= kEdgeRatioMax))
    throw std::invalid_argument("edge refinement ratio outside [1.1, 16] and not 1");
  if (refinedBands < 1 || refinedBands > kEdgeBandsMax) throw std::invalid_argument("refined bands outside 1..4");
  // The fewest interior cells per band q for which every refined band can hold a whole number of
  // cells e whose mean size q/e gives the profile an exponent alpha in [1/4, 4] (monotone and
  // smooth: never a run of equal cells ending in a jump), e nearest to the geometric grading's
  // count.
  for (int q = 1; q <= kLargestUnit; ++q) {
    std::vector<int> cells(refinedBands);
    bool fits = true;
    for (int k = 0; k < refinedBands && fits; ++k) {
      const double a = bandEndSize(ratio, refinedBands, k), c = bandEndSize(ratio, refinedBands, k + 1);
      const int lo = static_cast<int>(std::ceil(q / (a + 0.8 * (c - a)))),  // alpha >= 1/4
          hi = static_cast<int>(std::floor(q / (a + 0.2 * (c - a))));       // alpha <= 4
      const double geometric = q * (1.0 / a - 1.0 / c) / std::log(c / a);
      cells[k] = std::clamp(static_cast<int>(std::lround(geometric)), lo, hi);
      fits = lo <= hi;
    }
    if (!fits) continue;
    bandCells_.assign(kGradingBands, q);
    alpha_.resize(refinedBands);
    for (int k = 0; k < refinedBands; ++k) {
      bandCells_[k] = bandCells_[kGradingBands - 1 - k] = cells[k];
      const double a = bandEndSize(ratio, refinedBands, k), c = bandEndSize(ratio, refinedBands, k + 1);
      const double mean = double(q) / cells[k];
      alpha_[k] = (c - a) / (mean - a) - 1.0;
    }
    unit_ = 0;
    for (int e : bandCells_) unit_ += e;
    return;
  }
  throw std::invalid_argument("edge refinement ratio too close to 1 for a whole number of cells per band");
}

int EdgeMap::cellsInBand(int band, int n) const {
  if (uniform()) return 0;  // bands need not hold whole cells on a uniform mesh
  return bandCells_[band] * (n / unit_);
}

std::vector<double> EdgeMap::nodes(int n, double length) const {
  std::vector<double> x(n + 1);
  if (uniform()) {
    const double h = length / n;
    for (int i = 0; i <= n; ++i) x[i] = i * h;
    return x;
  }
  if (n % unit_ != 0) throw std::invalid_argument("cells not a multiple of the edge grading's unit");
  const int m = n / unit_;
  int node = 0;
  for (int band = 0; band < kGradingBands / 2; ++band) {  // the left half; the right one mirrors it
    const double x0 = length * band / kGradingBands, width = length / kGradingBands;
    const int cells = bandCells_[band] * m;
    for (int j = 0; j < cells; ++j, ++node) {
      const double t = double(j) / cells;
      if (band >= refinedBands_) {
        x[node] = x0 + width * t;
        continue;
      }
      const double a = bandEndSize(ratio_, refinedBands_, band), c = bandEndSize(ratio_, refinedBands_, band + 1);
      const double alpha = alpha_[band];
      const double meanSize = double(bandCells_[kGradingBands / 2]) / bandCells_[band];  // q / e, interior size 1
      x[node] = x0 + width * (a * t + (c - a) * std::pow(t, alpha + 1.0) / (alpha + 1.0)) / meanSize;
    }
  }
  x[n / 2] = 0.5 * length;
  for (int i = 0; i < n / 2; ++i) x[n - i] = length - x[i];
  return x;
}

int refinedBandsOf(double width, double length) {
  if (width <= 0) return 1;
  const double bands = width / (length / kGradingBands);
  const long k = std::lround(bands);
  if (k < 1 || std::fabs(bands - k) > 1e-9 * bands) return 0;
  return static_cast<int>(k);
}

int MeshAxis::cellAt(double x) const {
  const auto it = std::upper_bound(nodes.begin(), nodes.end(), x);
  return std::clamp(static_cast<int>(it - nodes.begin()) - 1, 0, cells() - 1);
}

int MeshAxis::nearestNode(double x) const {
  const int i = cellAt(x);
  return x - nodes[i] <= nodes[i + 1] - x ? i : i + 1;
}

double MeshAxis::unitCentre(int cell) const {
  if (uniform()) return (cell + 0.5) / cells();
  return 0.5 * (nodes[cell] + nodes[cell + 1]) / length();
}

MeshAxis makeMeshAxis(const EdgeGrading& grading, int n, double length) {
  MeshAxis axis;
  const EdgeMap map(grading.ratio, grading.uniform() ? 1 : refinedBandsOf(grading.band, length));
  axis.nodes = map.nodes(n, length);
  if (map.uniform()) {
    axis.widthClass.assign(n, 0);
    axis.classWidth = {length / n};
    return axis;
  }
  // The refined cells of the left side each have their class (the right side mirrors them), the
  // uniform interior one class of width L / (10 q).
  int refined = 0;
  for (int k = 0; k < map.refinedBands(); ++k) refined += map.cellsInBand(k, n);
  for (int i = 0; i < refined; ++i) axis.classWidth.push_back(axis.nodes[i + 1] - axis.nodes[i]);
  axis.classWidth.push_back(length / kGradingBands / map.cellsInBand(kGradingBands / 2, n));
  axis.widthClass.resize(n);
  for (int i = 0; i < n; ++i) {
    const int mirror = std::min(i, n - 1 - i);
    axis.widthClass[i] = mirror < refined ? mirror : refined;
  }
  return axis;
}

std::string describeEdgeGrading(const EdgeGrading& grading, int n, double length) {
  const MeshAxis axis = makeMeshAxis(grading, n, length);
  char text[300];
  if (axis.uniform()) {
    std::snprintf(text, sizeof text, "uniform, element %.4g m", axis.classWidth[0]);
    return text;
  }
  const EdgeMap map(grading.ratio, refinedBandsOf(grading.band, length));
  std::string perBand;
  for (int k = 0; k < kGradingBands; ++k) perBand += (k ? " " : "") + std::to_string(map.cellsInBand(k, n));
  std::snprintf(text, sizeof text,
                "graded toward the edges (ratio %g over %d band(s) of L/10): edge element %.4g m, interior %.4g m; "
                "cells per band %s (n a multiple of %d)",
                grading.ratio, map.refinedBands(), axis.classWidth.front(), axis.classWidth.back(), perBand.c_str(),
                map.cellsPerUnit());
  return text;
}

}  // namespace gradfric::fem
