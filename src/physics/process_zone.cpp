#include "gradfric/physics/process_zone.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric {

namespace {

// The distinct coordinates of a tensor-product grid, merged within a relative tolerance.
std::vector<double> gridLines(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> lines;
  const double span = values.empty() ? 0.0 : values.back() - values.front();
  for (double v : values)
    if (lines.empty() || v - lines.back() > 1e-9 * span) lines.push_back(v);
  return lines;
}

int lineIndex(const std::vector<double>& lines, double v) {
  const auto it = std::lower_bound(lines.begin(), lines.end(), v - 1e-9 * (lines.back() - lines.front()));
  return static_cast<int>(it - lines.begin());
}

double quantile(std::vector<double> values, double q) {
  const std::size_t k = static_cast<std::size_t>(q * (values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

ProcessZone measureProcessZone(const WeakeningTimes& t, double latestStart) {
  ProcessZone zone;
  if (t.x.empty()) return zone;
  const std::vector<double> xs = gridLines(t.x), ys = gridLines(t.y);
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size());
  std::vector<double> start(static_cast<std::size_t>(nx) * ny, -1.0);
  for (std::size_t i = 0; i < t.x.size(); ++i) start[lineIndex(ys, t.y[i]) * nx + lineIndex(xs, t.x[i])] = t.start[i];
  // d t_start / d coordinate along one grid axis at (i, j): central where both neighbours weakened.
  auto slope = [&](int i, int j, int di, int dj, const std::vector<double>& lines, double* spacing) {
    const int k = di ? i : j, n = di ? nx : ny;
    const double here = start[j * nx + i];
    const bool before = k > 0 && start[(j - dj) * nx + (i - di)] >= 0;
    const bool after = k + 1 < n && start[(j + dj) * nx + (i + di)] >= 0;
    *spacing = k + 1 < n ? lines[k + 1] - lines[k] : lines[k] - lines[k - 1];
    if (before && after)
      return (start[(j + dj) * nx + (i + di)] - start[(j - dj) * nx + (i - di)]) / (lines[k + 1] - lines[k - 1]);
    if (after) return (start[(j + dj) * nx + (i + di)] - here) / (lines[k + 1] - lines[k]);
    if (before) return (here - start[(j - dj) * nx + (i - di)]) / (lines[k] - lines[k - 1]);
    return 0.0;
  };
  std::vector<double> lengths, elements;
  for (std::size_t n = 0; n < t.x.size(); ++n) {
    if (t.start[n] < 0 || t.start[n] > latestStart || t.end[n] < t.start[n]) continue;
    const int i = lineIndex(xs, t.x[n]), j = lineIndex(ys, t.y[n]);
    double hx = 0, hy = 0;
    const double gx = nx > 1 ? slope(i, j, 1, 0, xs, &hx) : 0.0;
    const double gy = ny > 1 ? slope(i, j, 0, 1, ys, &hy) : 0.0;
    const double slowness = std::hypot(gx, gy);
    if (!(slowness > 0)) continue;  // the whole neighbourhood weakened at once: no front to measure here
    const double length = (t.end[n] - t.start[n]) / slowness;
    const double h = (std::fabs(gx) * hx + std::fabs(gy) * hy) / (std::fabs(gx) + std::fabs(gy));
    lengths.push_back(length);
    elements.push_back(length / h);
  }
  zone.nodes = static_cast<int>(lengths.size());
  if (lengths.empty()) return zone;
  zone.median = quantile(lengths, 0.5);
  zone.low = quantile(lengths, 0.1);
  zone.medianElements = quantile(elements, 0.5);
  zone.lowElements = quantile(elements, 0.1);
  return zone;
}

}  // namespace gradfric
