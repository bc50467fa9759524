// The procedure of include/gradfric/core/verification.hpp (Eca and Hoekstra 2014, section 4;
// docs/verification.md):
//  1. the differences of successive members (fine to coarse) classify the ladder: one within its
//     95 % half-width gives no signal; otherwise the same sign throughout is monotone, else
//     oscillatory; a monotone ladder converges where the least-squares fit phi_0 + alpha h^p has
//     p >= 0.5 (0 < p < 0.5: too slow to bound, our one departure), an oscillatory one where the
//     differences' own power-law fit shrinks with h;
//  2. the error estimate: the fit alpha h^p where 0.5 <= p < formal order (safety factor 1.25),
//     else the fixed-order fits alpha h, alpha h^2, alpha_1 h + alpha_2 h^2 that have a degree of
//     freedom, the one of the smallest standard deviation (safety factor 3); each fit unweighted
//     and with weights 1/h, the one of the smaller standard deviation kept;
//  3. U = Fs eps + U_s + |phi - fit| where U_s < Delta_phi (the data range per interval), else
//     3 U_s / Delta_phi (eps + U_s + |phi - fit|); an oscillatory ladder at least 3 (max - min),
//     the data-range bound, which alone judges a ladder without signal;
//  4. the 95 % half-width of the member's distance to phi_0 (or of the range) is added.
#include "gradfric/core/verification.hpp"

#include "gradfric/campaign/statistics.hpp"  // t95

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gradfric::verification {

namespace {

// A least-squares fit phi(h) = c_0 + sum_k c_k h^{exponent_k}.
struct Fit {
  std::vector<double> exponents, coefficients;
  bool weighted = false;
  double stdDev = INFINITY;  // U_s
  double at(double h) const {
    double phi = coefficients[0];
    for (std::size_t k = 0; k < exponents.size(); ++k) phi += coefficients[k + 1] * std::pow(h, exponents[k]);
    return phi;
  }
};

// Weighted linear least squares by the normal equations (at most 3 unknowns); weights 1/h scaled to
// sum n, as Eca and Hoekstra's. U_s = sqrt(sum w r^2 / (n - unknowns)), 0 for an exact fit.
Fit fitLinear(const std::vector<Member>& m, const std::vector<double>& exponents, bool weighted,
              const std::vector<double>& values) {
  const std::size_t n = m.size(), k = exponents.size() + 1;
  std::vector<double> w(n, 1.0);
  if (weighted) {
    double sum = 0;
    for (const Member& x : m) sum += 1.0 / x.h;
    for (std::size_t i = 0; i < n; ++i) w[i] = n * (1.0 / m[i].h) / sum;
  }
  double a[3][4] = {};
  for (std::size_t i = 0; i < n; ++i) {
    double basis[3] = {1, 0, 0};
    for (std::size_t j = 1; j < k; ++j) basis[j] = std::pow(m[i].h, exponents[j - 1]);
    for (std::size_t r = 0; r < k; ++r) {
      for (std::size_t c = 0; c < k; ++c) a[r][c] += w[i] * basis[r] * basis[c];
      a[r][k] += w[i] * basis[r] * values[i];
    }
  }
  for (std::size_t p = 0; p < k; ++p)  // Gaussian elimination with partial pivoting
    for (std::size_t r = p + 1; r < k; ++r) {
      if (std::fabs(a[r][p]) > std::fabs(a[p][p])) std::swap(a[r], a[p]);
      const double f = a[r][p] / a[p][p];
      for (std::size_t c = p; c <= k; ++c) a[r][c] -= f * a[p][c];
    }
  Fit fit{exponents, std::vector<double>(k), weighted};
  for (std::size_t r = k; r-- > 0;) {
    double s = a[r][k];
    for (std::size_t c = r + 1; c < k; ++c) s -= a[r][c] * fit.coefficients[c];
    fit.coefficients[r] = s / a[r][r];
  }
  double residual = 0;
  for (std::size_t i = 0; i < n; ++i) residual += w[i] * std::pow(values[i] - fit.at(m[i].h), 2);
  fit.stdDev = n > k ? std::sqrt(residual / double(n - k)) : 0.0;
  if (!std::isfinite(fit.stdDev)) fit.stdDev = INFINITY;  // a singular system
  return fit;
}

std::vector<double> valuesOf(const std::vector<Member>& m) {
  std::vector<double> v;
  for (const Member& x : m) v.push_back(x.value);
  return v;
}

// The fit of the smaller standard deviation, unweighted on a tie.
Fit better(const Fit& a, const Fit& b) { return b.stdDev < a.stdDev ? b : a; }

Fit bestOf(const std::vector<Member>& m, const std::vector<double>& exponents) {
  const std::vector<double> v = valuesOf(m);
  return better(fitLinear(m, exponents, false, v), fitLinear(m, exponents, true, v));
}

// phi_0 + alpha h^p: p by a scan over [-8, 8] (or near a known p) refined by golden sections (for
// three members the fit is exact at the p the two differences give).
Fit observedOrderFit(const std::vector<Member>& m, const Fit* near = nullptr) {
  const std::vector<double> values = valuesOf(m);
  const auto residual = [&](double p, bool weighted) {
    const Fit f = fitLinear(m, {p}, weighted, values);
    double s = 0;
    for (const Member& x : m) s += std::pow(x.value - f.at(x.h), 2);
    return s;
  };
  Fit best;
  for (bool weighted : {false, true}) {
    if (near && near->weighted != weighted) continue;
    double bestP = 1, bestS = INFINITY, step = 0.01;
    if (near) {
      bestP = near->exponents[0], step = 0.05;
    } else {
      for (int k = -800; k <= 800; ++k) {
        const double p = k / 100.0, s = k == 0 ? INFINITY : residual(p, weighted);  // h^0 duplicates the constant
        if (s < bestS) bestS = s, bestP = p;
      }
    }
    double lo = bestP - step, hi = bestP + step;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < 60; ++i) {
      const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
      if (residual(x1, weighted) < residual(x2, weighted))
        hi = x2;
      else
        lo = x1;
    }
    best = better(best, fitLinear(m, {(lo + hi) / 2}, weighted, values));
  }
  return best;
}

// The fixed-order fits with a degree of freedom (n > unknowns), the smallest standard deviation.
Fit fixedOrderFit(const std::vector<Member>& m) {
  Fit best = better(bestOf(m, {1.0}), bestOf(m, {2.0}));
  if (m.size() > 3) best = better(best, bestOf(m, {1.0, 2.0}));
  return best;
}

// The 95 % half-width of sum_j c_j phi_j over independent members (Student's t of the smallest
// sample used); 0 when every member used is deterministic.
double halfWidth(const std::vector<Member>& m, const std::vector<double>& c) {
  double variance = 0;
  int smallest = 0;
  for (std::size_t j = 0; j < m.size(); ++j) {
    if (c[j] == 0.0 || m[j].stdError == 0.0) continue;
    variance += c[j] * c[j] * m[j].stdError * m[j].stdError;
    smallest = smallest == 0 ? m[j].samples : std::min(smallest, m[j].samples);
  }
  return variance == 0.0 ? 0.0 : campaign::t95(smallest - 1) * std::sqrt(variance);
}

// The half-width of phi_member - phi_0: phi_0 is linear in the data at fixed exponents; the
// observed order moves with the data too, so that fit's sensitivities are taken by refitting it.
double fitHalfWidth(const std::vector<Member>& m, const Fit& fit, std::size_t member, bool observed) {
  if (std::all_of(m.begin(), m.end(), [](const Member& x) { return x.stdError == 0.0; })) return 0.0;
  std::vector<double> c(m.size());
  for (std::size_t j = 0; j < m.size(); ++j) {
    if (observed) {
      std::vector<Member> moved = m;
      const double step = 1e-3 * m[j].stdError;
      moved[j].value += step;
      const Fit refit = observedOrderFit(moved, &fit);
      c[j] = ((j == member ? 1.0 : 0.0) * step - (refit.coefficients[0] - fit.coefficients[0])) / step;
    } else {
      std::vector<double> unit(m.size(), 0.0);
      unit[j] = 1;
      c[j] = (j == member ? 1.0 : 0.0) - fitLinear(m, fit.exponents, fit.weighted, unit).coefficients[0];
    }
  }
  return halfWidth(m, c);
}

ErrorFit fitName(const Fit& f, bool observed) {
  if (observed) return ErrorFit::ObservedOrder;
  if (f.exponents.size() == 2) return ErrorFit::FirstAndSecondOrder;
  return f.exponents[0] == 1.0 ? ErrorFit::FirstOrder : ErrorFit::SecondOrder;
}

}  // namespace

Verdict judge(const std::vector<Member>& ladder, int member, double formalOrder) {
  Verdict v;
  v.member = member;
  v.value = v.extrapolated = ladder.at(member).value;
  std::vector<std::size_t> order(ladder.size());  // fine to coarse
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ladder[a].h < ladder[b].h; });
  std::vector<Member> m;
  std::size_t at = 0;
  for (std::size_t i : order) {
    if (i == std::size_t(member)) at = m.size();
    m.push_back(ladder[i]);
  }
  const std::size_t n = m.size();
  for (std::size_t i = 1; i < n; ++i)
    if (!(m[i].h > m[i - 1].h)) return v;  // two members of one cell size: not a ladder
  if (n < 3) return v;
  const auto [low, high] = std::minmax_element(m.begin(), m.end(), [](const Member& a, const Member& b) { return a.value < b.value; });
  v.dataRange = (high->value - low->value) / double(n - 1);
  std::vector<double> rangeOf(n, 0.0);
  rangeOf[high - m.begin()] += 1;
  rangeOf[low - m.begin()] -= 1;
  // The data-range bound, 3 (max - min) with its half-width.
  const double rangeHalfWidth = halfWidth(m, rangeOf), rangeBound = 3 * (high->value - low->value + rangeHalfWidth);
  bool noSignal = false, sameSign = true;
  std::vector<double> logH, logD;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double d = m[i + 1].value - m[i].value;
    std::vector<double> c(n, 0.0);
    c[i] = -1, c[i + 1] = 1;
    const double h = halfWidth(m, c);
    noSignal = noSignal || std::fabs(d) <= h;  // a zero difference has no sign either
    sameSign = sameSign && d * (m[1].value - m[0].value) > 0;
    logH.push_back(std::log(m[i + 1].h));
    logD.push_back(std::log(std::fabs(d)));
  }
  if (noSignal) {  // the sign of a difference is not known
    v.convergence = Convergence::NoSignal;
    v.safetyFactor = 3;
    v.halfWidth = 3 * rangeHalfWidth;
    v.uncertainty = rangeBound;
    return v;
  }
  const Fit observed = observedOrderFit(m);
  v.order = observed.exponents[0];
  if (sameSign) {
    v.convergence = v.order >= 0.5 ? Convergence::Monotone
                    : v.order > 0  ? Convergence::SlowConvergence
                                   : Convergence::MonotoneDivergence;
  } else {  // the differences' power law |d| ~ h^p*: slope of the least-squares line in log-log
    const double mh = std::accumulate(logH.begin(), logH.end(), 0.0) / logH.size();
    const double md = std::accumulate(logD.begin(), logD.end(), 0.0) / logD.size();
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < logH.size(); ++i) sxy += (logH[i] - mh) * (logD[i] - md), sxx += (logH[i] - mh) * (logH[i] - mh);
    v.order = sxy / sxx;  // the rate at which the oscillation shrinks: a fit of phi has none
    v.convergence = v.order > 0 ? Convergence::Oscillatory : Convergence::OscillatoryDivergence;
  }
  if (!v.bounded()) return v;
  const bool inRange = v.convergence == Convergence::Monotone && v.order < formalOrder;
  const Fit fit = inRange ? observed : fixedOrderFit(m);
  v.fit = fitName(fit, inRange);
  v.safetyFactor = inRange ? 1.25 : 3.0;
  v.extrapolated = fit.coefficients[0];
  v.fitStdDev = fit.stdDev;
  const double onFit = fit.at(m[at].h), error = std::fabs(onFit - v.extrapolated), off = std::fabs(m[at].value - onFit);
  // The half-width joins the error estimate under the safety factor: the observed order of noisy
  // means is itself uncertain, which the half-width at the fitted order does not show.
  v.halfWidth = fitHalfWidth(m, fit, at, inRange);
  v.uncertainty = v.fitStdDev < v.dataRange ? v.safetyFactor * (error + v.halfWidth) + v.fitStdDev + off
                                            : 3 * v.fitStdDev / v.dataRange * (error + v.halfWidth + v.fitStdDev + off);
  if (v.convergence == Convergence::Oscillatory && rangeBound > v.uncertainty) {
    v.uncertainty = rangeBound;
    v.halfWidth = 3 * rangeHalfWidth;
  }
  return v;
}

const char* toString(Convergence c) {
  static const char* const names[] = {"too few members",        "no signal",
                                      "monotone",               "slow convergence (order below 0.5)",
                                      "oscillatory",            "monotone divergence",
                                      "oscillatory divergence"};
  return names[static_cast<int>(c)];
}

const char* toString(ErrorFit f) {
  static const char* const names[] = {"observed order", "first order", "second order", "first and second order",
                                      "data range"};
  return names[static_cast<int>(f)];
}

}  // namespace gradfric::verification
