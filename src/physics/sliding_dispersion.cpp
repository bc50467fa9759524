#include "gradfric/physics/sliding_dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gradfric {
namespace {

using Complex = std::complex<double>;
using Function = std::function<Complex(Complex)>;
const Complex I(0.0, 1.0);

// Roots closer to the real axis than this (in eta) are counted as neutral: the contour runs at
// this height so that the mu = 1 root, exactly on the axis, is not on it.
constexpr double kNeutralBand = 1e-9;

void checkArguments(double nu, int kSign) {
  if (!(nu > 0.0 && nu < 0.5)) throw std::invalid_argument("sliding dispersion: nu must lie in (0, 0.5)");
  if (kSign != 1 && kSign != -1) throw std::invalid_argument("sliding dispersion: kSign must be +1 or -1");
}

// sqrt(1 - w^2) for k > 0: Re > 0 off the real axis (decay into the body); on the axis, for
// |w| > 1, the limit from Im w > 0. In the closed upper half plane -i sqrt(w-1) sqrt(w+1) is that
// function (each factor's argument lies in (0, pi)) and, unlike sqrt(1 - w*w), does not depend on
// the sign of a rounded zero imaginary part.
Complex decayingRoot(Complex w) {
  if (w.imag() >= 0.0) {
    const Complex v(w.real(), w.imag() + 0.0);  // -0.0 + 0.0 = +0.0
    return -I * std::sqrt(v - 1.0) * std::sqrt(v + 1.0);
  }
  return std::sqrt(1.0 - w * w);
}

struct Branches {
  Complex alpha, beta;
};

Branches branches(Complex eta, double r) { return {decayingRoot(r * eta), decayingRoot(eta)}; }

// D for k > 0.
Complex dispersionUpper(Complex eta, double mu, double r) {
  const auto [alpha, beta] = branches(eta, r);
  return I * alpha * eta * eta - mu * (2.0 - eta * eta - 2.0 * alpha * beta);
}

// D / eta^2 for k > 0, without the cancellation in 2 - 2 alpha beta near eta = 0:
// 2 - 2 alpha beta = 2 (1 - alpha^2 beta^2) / (1 + alpha beta) = 2 eta^2 (1 + r^2 - r^2 eta^2) / (1 + alpha beta).
// (Only near 0: 1 + alpha beta vanishes on the real axis beyond c_p.)
Complex reducedUpper(Complex eta, double mu, double r) {
  const auto [alpha, beta] = branches(eta, r);
  if (std::abs(eta) < 0.5)
    return I * alpha - mu * (2.0 * (1.0 + r * r - r * r * eta * eta) / (1.0 + alpha * beta) - 1.0);
  return (I * alpha * eta * eta - mu * (2.0 - eta * eta - 2.0 * alpha * beta)) / (eta * eta);
}

Complex derivativeUpper(Complex eta, double mu, double r) {
  const auto [alpha, beta] = branches(eta, r);
  const Complex dAlpha = -r * r * eta / alpha;
  const Complex dBeta = -eta / beta;
  return I * dAlpha * eta * eta + 2.0 * I * alpha * eta - mu * (-2.0 * eta - 2.0 * dAlpha * beta - 2.0 * alpha * dBeta);
}

// The change of arg f along a -> b. A step is accepted only when f changes by less than a
// quarter of its size over each half, so the argument cannot jump by a turn unseen; near a zero
// close to the segment the steps shrink to its distance.
double argumentChange(const Function& f, Complex a, Complex b) {
  double total = 0.0;
  double t = 0.0;
  double h = 1.0 / 64.0;
  Complex fa = f(a);
  if (fa == 0.0) throw std::runtime_error("sliding dispersion: a root lies on the counting contour");
  while (t < 1.0) {
    double step = std::min(h, 1.0 - t);
    for (;;) {
      const Complex fm = f(a + (b - a) * (t + 0.5 * step));
      const Complex fb = f(a + (b - a) * (t + step));
      const Complex q1 = fm / fa;
      const Complex q2 = fb / fm;
      const bool smooth = std::abs(q1 - 1.0) < 0.25 && std::abs(q2 - 1.0) < 0.25;
      if (smooth || step < 1e-15) {
        if (!smooth || fb == 0.0 || !std::isfinite(std::abs(q1 * q2)))
          throw std::runtime_error("sliding dispersion: a root lies on the counting contour");
        total += std::arg(q1) + std::arg(q2);
        fa = fb;
        t += step;
        break;
      }
      step *= 0.5;
    }
    h = 2.0 * step;
  }
  return total;
}

struct Box {
  double x0, x1, y0, y1;
};

int windingNumber(const Function& f, const Box& b) {
  const Complex c00(b.x0, b.y0), c10(b.x1, b.y0), c11(b.x1, b.y1), c01(b.x0, b.y1);
  const double turns = (argumentChange(f, c00, c10) + argumentChange(f, c10, c11) + argumentChange(f, c11, c01) +
                        argumentChange(f, c01, c00)) /
                       (2.0 * M_PI);
  const double n = std::round(turns);
  if (std::abs(turns - n) > 0.05)
    throw std::runtime_error("sliding dispersion: winding " + std::to_string(turns) + " is not an integer");
  return static_cast<int>(n);
}

// Large |eta| in the upper half plane: alpha ~ -i r eta, so D / eta^2 = i alpha - mu g with
// |g| <= 1 + 2 r + O(1/|eta|^2); no root beyond |eta| ~ mu (1 + 2 r) / r. Four times that, plus 4.
double enclosingHalfWidth(double mu, double r) { return 4.0 + 4.0 * std::abs(mu) * (1.0 + 2.0 * r) / r; }

Complex newtonUpper(Complex eta, double mu, double r) {
  for (int it = 0; it < 60; ++it) {
    const Complex step = dispersionUpper(eta, mu, r) / derivativeUpper(eta, mu, r);
    eta -= step;
    if (eta.imag() < 0.0) eta.imag(0.0);  // stay on the closed growing side, where D is the analytic one
    if (std::abs(step) < 1e-15 * (1.0 + std::abs(eta))) break;
  }
  return eta;
}

// Every root in the box (n of them by the count): bisect along the longer side until the box is
// 1e-4 wide, then Newton from its centre. A split line through a root makes a half's count fail
// or not add up; the split is then moved.
void collectRoots(const Function& f, const Box& box, int n, double mu, double r, std::vector<Complex>& roots) {
  if (n <= 0) return;
  const double width = box.x1 - box.x0, height = box.y1 - box.y0;
  if (std::max(width, height) < 1e-4) {
    const Complex centre(0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1));
    const Complex root = newtonUpper(centre, mu, r);
    if (std::abs(root - centre) > 1e-2)
      throw std::runtime_error("sliding dispersion: Newton left the bracketing box");
    roots.push_back(root);
    return;
  }
  for (double fraction : {0.5, 0.5123, 0.4871, 0.5379, 0.4619}) {
    Box first = box, second = box;
    if (width >= height) {
      first.x1 = second.x0 = box.x0 + fraction * width;
    } else {
      first.y1 = second.y0 = box.y0 + fraction * height;
    }
    try {
      const int n1 = windingNumber(f, first);
      const int n2 = windingNumber(f, second);
      if (n1 < 0 || n2 < 0 || n1 + n2 != n) continue;
      collectRoots(f, first, n1, mu, r, roots);
      collectRoots(f, second, n2, mu, r, roots);
      return;
    } catch (const std::runtime_error&) {
      continue;
    }
  }
  throw std::runtime_error("sliding dispersion: could not split the box around a root");
}

}  // namespace

double shearToPressureSpeedRatio(double nu) { return std::sqrt((1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)); }

std::complex<double> slidingDispersion(std::complex<double> eta, double mu, double nu, int kSign) {
  checkArguments(nu, kSign);
  const double r = shearToPressureSpeedRatio(nu);
  if (kSign > 0) return dispersionUpper(eta, mu, r);
  return std::conj(dispersionUpper(std::conj(eta), mu, r));  // k < 0: the conjugate problem
}

int countGrowingSlidingRoots(double mu, double nu, int kSign, double halfWidth) {
  checkArguments(nu, kSign);
  const double r = shearToPressureSpeedRatio(nu);
  const double R = halfWidth > 0.0 ? halfWidth : enclosingHalfWidth(mu, r);
  // D / eta^2: the double root eta = 0 (a rigid shift) is divided out, and the contour may pass
  // next to it.
  if (kSign > 0) {
    const Function f = [mu, r](Complex eta) { return reducedUpper(eta, mu, r); };
    return windingNumber(f, {-R, R, kNeutralBand, R});
  }
  // k < 0: the lower half plane, counter-clockwise, with D_-(eta) = conj(D_+(conj eta)) evaluated
  // as such (the count checks the symmetry rather than assuming it).
  const Function f = [mu, r](Complex eta) { return std::conj(reducedUpper(std::conj(eta), mu, r)); };
  return windingNumber(f, {-R, R, -R, -kNeutralBand});
}

SlidingMode growingSlidingMode(double mu, double nu) {
  checkArguments(nu, 1);
  const double r = shearToPressureSpeedRatio(nu);
  const double R = enclosingHalfWidth(mu, r);
  const Function f = [mu, r](Complex eta) { return reducedUpper(eta, mu, r); };
  const Box box{-R, R, kNeutralBand, R};
  const int n = windingNumber(f, box);
  SlidingMode mode;
  if (n <= 0) return mode;
  std::vector<Complex> roots;
  collectRoots(f, box, n, mu, r, roots);
  const auto fastest =
      std::max_element(roots.begin(), roots.end(), [](Complex a, Complex b) { return a.imag() < b.imag(); });
  if (fastest == roots.end() || !(fastest->imag() > 0.0)) return mode;
  mode.growing = true;
  mode.eta = *fastest;
  mode.direction = fastest->real() > 0.0 ? 1 : -1;  // phase velocity c_s Re(eta) against +x, the sliding
  return mode;
}

double slidingGrowthRate(double mu, double nu, double shearSpeed, double wavelength) {
  const SlidingMode mode = growingSlidingMode(mu, nu);
  if (!mode.growing) return 0.0;
  return 2.0 * M_PI / wavelength * shearSpeed * mode.eta.imag();
}

}  // namespace gradfric
