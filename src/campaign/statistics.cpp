#include "gradfric/campaign/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gradfric::campaign {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Continued fraction of the incomplete beta function (modified Lentz).
double betaContinuedFraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < 1e-15) break;
  }
  return h;
}

// Student t cumulative distribution function.
double studentTCdf(double t, int dof) {
  const double nu = dof;
  const double tail = 0.5 * incompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
  return t >= 0 ? 1.0 - tail : tail;
}
}  // namespace

double incompleteBeta(double a, double b, double x) {
  if (!(a > 0 && b > 0) || x < 0 || x > 1) throw std::invalid_argument("incompleteBeta: a, b > 0 and 0 <= x <= 1");
  if (x == 0.0 || x == 1.0) return x;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * betaContinuedFraction(a, b, x) / a;
  return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

double studentTQuantile(double p, int dof) {
  if (!(p > 0 && p < 1) || dof < 1) throw std::invalid_argument("studentTQuantile: 0 < p < 1 and dof >= 1");
  if (p == 0.5) return 0.0;
  if (p < 0.5) return -studentTQuantile(1.0 - p, dof);
  double lo = 0.0, hi = 1.0;
  while (studentTCdf(hi, dof) < p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (studentTCdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double t95(int dof) { return dof >= 1 ? studentTQuantile(0.975, dof) : kNaN; }

Summary summarise(const std::vector<double>& values) {
  Summary s;
  double sum = 0.0;
  for (double v : values)
    if (std::isfinite(v)) {
      sum += v;
      ++s.count;
    }
  if (s.count == 0) {
    s.mean = s.stdDev = s.stdError = s.ciLow = s.ciHigh = kNaN;
    return s;
  }
  s.mean = sum / s.count;
  if (s.count < 2) {
    s.stdDev = s.stdError = s.ciLow = s.ciHigh = kNaN;
    return s;
  }
  double squares = 0.0;  // two-pass: no cancellation for values close together (mu ~ 1 +- 1 %)
  for (double v : values)
    if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
  s.stdDev = std::sqrt(squares / (s.count - 1));
  s.stdError = s.stdDev / std::sqrt(static_cast<double>(s.count));
  const double t = t95(s.count - 1);
  s.ciLow = s.mean - t * s.stdError;
  s.ciHigh = s.mean + t * s.stdError;
  return s;
}

RelativeVariation relativeVariation(const Summary& point, const Summary& reference, bool isReference) {
  if (isReference) {
    const double zero = point.count > 0 ? 0.0 : kNaN;
    return {zero, zero, zero};
  }
  RelativeVariation r;
  const double m0 = reference.mean;
  r.value = (point.mean - m0) / m0;
  const double a = point.stdError / m0;
  const double b = point.mean * reference.stdError / (m0 * m0);
  r.error = std::sqrt(a * a + b * b);
  r.halfWidth = t95(std::min(point.count, reference.count) - 1) * r.error;
  return r;
}

RelativeVariation pairedRelativeVariation(const std::vector<double>& point, const std::vector<double>& reference) {
  std::vector<double> x, y;
  for (size_t i = 0; i < point.size() && i < reference.size(); ++i)
    if (std::isfinite(point[i]) && std::isfinite(reference[i])) {
      x.push_back(point[i]);
      y.push_back(reference[i]);
    }
  RelativeVariation r{kNaN, kNaN, kNaN};
  if (x.empty()) return r;
  const Summary sx = summarise(x), sy = summarise(y);
  const double m = sx.mean, m0 = sy.mean;
  r.value = (m - m0) / m0;
  if (x.size() < 2) return r;
  std::vector<double> z(x.size());
  for (size_t i = 0; i < x.size(); ++i) z[i] = x[i] / m0 - m * y[i] / (m0 * m0);
  r.error = summarise(z).stdError;
  r.halfWidth = t95(static_cast<int>(x.size()) - 1) * r.error;
  return r;
}

std::vector<PointStatistics> pointStatistics(int realisations, const std::vector<int>& reference,
                                             const std::vector<std::vector<double>>& tables,
                                             const std::vector<signed char>& peakConfirmed,
                                             const std::vector<unsigned char>& done, bool paired) {
  const size_t points = reference.size();
  const size_t R = static_cast<size_t>(realisations);
  bool sized = peakConfirmed.size() == points * R && done.size() == points * R;
  for (const auto& table : tables) sized = sized && table.size() == points * R;
  if (!sized) throw std::invalid_argument("pointStatistics: tables must be points x realisations");
  std::vector<PointStatistics> out(points);
  for (size_t p = 0; p < points; ++p) {
    for (size_t r = 0; r < R; ++r) {
      const size_t i = p * R + r;
      if (!done[i]) continue;
      ++out[p].finished;
      if (!peakConfirmed[i]) ++out[p].peaksUnconfirmed;
    }
    for (const auto& table : tables) {
      std::vector<double> values;
      for (size_t r = 0; r < R; ++r)
        if (done[p * R + r]) values.push_back(table[p * R + r]);
      out[p].observables.push_back({summarise(values), {}});
    }
  }
  for (size_t p = 0; p < points; ++p) {
    const int ref = reference[p];
    for (size_t o = 0; o < tables.size(); ++o) {
      RelativeVariation& relative = out[p].observables[o].relative;
      if (ref < 0 || static_cast<size_t>(ref) >= points) {
        relative = {kNaN, kNaN, kNaN};
        continue;
      }
      const bool self = static_cast<size_t>(ref) == p;
      if (paired && !self) {
        // Realisation r of both points, where both finished.
        auto column = [&](size_t point, size_t other) {
          std::vector<double> v(R, kNaN);
          for (size_t r = 0; r < R; ++r)
            if (done[point * R + r] && done[other * R + r]) v[r] = tables[o][point * R + r];
          return v;
        };
        const size_t q = static_cast<size_t>(ref);
        relative = pairedRelativeVariation(column(p, q), column(q, p));
        continue;
      }
      relative = relativeVariation(out[p].observables[o].summary, out[ref].observables[o].summary, self);
    }
  }
  return out;
}

}  // namespace gradfric::campaign
