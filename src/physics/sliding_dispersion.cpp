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

// D for k > 0, with the memory K = |k| c_s T: the shear traction times (1 - i K eta) (the filtered
// pressure is p / (1 - i omega T), omega T = K eta for k > 0). K = 0: Coulomb, bit for bit.
Complex dispersionUpper(Complex eta, double mu, double r, double K) {
  const auto [alpha, beta] = branches(eta, r);
  const Complex shear = I * alpha * eta * eta;
  return (K == 0.0 ? shear : shear * (1.0 - I * K * eta)) - mu * (2.0 - eta * eta - 2.0 * alpha * beta);
}

// D / eta^2 for k > 0, without the cancellation in 2 - 2 alpha beta near eta = 0:
// 2 - 2 alpha beta = 2 (1 - alpha^2 beta^2) / (1 + alpha beta) = 2 eta^2 (1 + r^2 - r^2 eta^2) / (1 + alpha beta).
// (Only near 0: 1 + alpha beta vanishes on the real axis beyond c_p.)
Complex reducedUpper(Complex eta, double mu, double r, double K) {
  const auto [alpha, beta] = branches(eta, r);
  if (std::abs(eta) < 0.5) {
    const Complex shear = K == 0.0 ? I * alpha : I * alpha * (1.0 - I * K * eta);
    return shear - mu * (2.0 * (1.0 + r * r - r * r * eta * eta) / (1.0 + alpha * beta) - 1.0);
  }
  return dispersionUpper(eta, mu, r, K) / (eta * eta);
}

Complex derivativeUpper(Complex eta, double mu, double r, double K) {
  const auto [alpha, beta] = branches(eta, r);
  const Complex dAlpha = -r * r * eta / alpha;
  const Complex dBeta = -eta / beta;
  const Complex dShear = I * dAlpha * eta * eta + 2.0 * I * alpha * eta;
  const Complex dMemory = K == 0.0 ? Complex(0.0) : dShear * (-I * K * eta) + K * alpha * eta * eta;
  return dShear + dMemory - mu * (-2.0 * eta - 2.0 * dAlpha * beta - 2.0 * alpha * dBeta);
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

// Large |eta| in the upper half plane: alpha ~ -i r eta, so D / eta^2 = i alpha (1 - i K eta) - mu g
// with |g| <= 1 + 2 r + O(1/|eta|^2) and |1 - i K eta| >= 1 + K Im(eta) >= 1 for K >= 0; no root
// beyond |eta| ~ mu (1 + 2 r) / r, whatever the memory. Four times that, plus 4.
double enclosingHalfWidth(double mu, double r) { return 4.0 + 4.0 * std::abs(mu) * (1.0 + 2.0 * r) / r; }

Complex newtonUpper(Complex eta, double mu, double r, double K) {
  for (int it = 0; it < 60; ++it) {
    const Complex step = dispersionUpper(eta, mu, r, K) / derivativeUpper(eta, mu, r, K);
    eta -= step;
    if (eta.imag() < 0.0) eta.imag(0.0);  // stay on the closed growing side, where D is the analytic one
    if (std::abs(step) < 1e-15 * (1.0 + std::abs(eta))) break;
  }
  return eta;
}

// Every root in the box (n of them by the count): bisect along the longer side until the box is
// 1e-4 wide, then Newton from its centre. A split line through a root makes a half's count fail
// or not add up; the split is then moved.
void collectRoots(const Function& f, const Box& box, int n, double mu, double r, double K,
                  std::vector<Complex>& roots) {
  if (n <= 0) return;
  const double width = box.x1 - box.x0, height = box.y1 - box.y0;
  if (std::max(width, height) < 1e-4) {
    const Complex centre(0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1));
    const Complex root = newtonUpper(centre, mu, r, K);
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
      collectRoots(f, first, n1, mu, r, K, roots);
      collectRoots(f, second, n2, mu, r, K, roots);
      return;
    } catch (const std::runtime_error&) {
      continue;
    }
  }
  throw std::runtime_error("sliding dispersion: could not split the box around a root");
}

void checkMemory(double memory) {
  if (!(memory >= 0.0 && std::isfinite(memory)))
    throw std::invalid_argument("sliding dispersion: the memory K = |k| c_s T must be finite and >= 0");
}

// K Im(eta) (the growth rate times T) of a root followed by continuation in K from `start`, a
// root at K = 0: over a geometric grid in K (a linear predictor, Newton), then a golden-section
// refinement of the largest value. `until` > 0 ends the grid there (the flutter branch at K_c).
double largestScaledGrowth(Complex start, double mu, double r, double until) {
  std::vector<double> ks{0.0};
  std::vector<Complex> roots{start};
  const double last = until > 0.0 ? until : 100.0;
  for (double K = 1e-4; K < last; K *= std::pow(10.0, 1.0 / 64.0)) {
    const std::size_t n = roots.size();
    Complex guess = roots[n - 1];
    if (n >= 2) guess += (roots[n - 1] - roots[n - 2]) * (K - ks[n - 1]) / (ks[n - 1] - ks[n - 2]);
    if (guess.imag() < 0.0) guess.imag(0.0);
    const Complex root = newtonUpper(guess, mu, r, K);
    if (!(std::abs(dispersionUpper(root, mu, r, K)) < 1e-10 * (1.0 + std::abs(root))) ||
        std::abs(root - roots[n - 1]) > 0.05)
      throw std::runtime_error("sliding dispersion: the continuation in the memory lost the root");
    ks.push_back(K);
    roots.push_back(root);
  }
  std::size_t best = 0;
  for (std::size_t j = 1; j < ks.size(); ++j)
    if (ks[j] * roots[j].imag() > ks[best] * roots[best].imag()) best = j;
  if (best == 0 || !(roots[best].imag() > 0.0)) return 0.0;
  if (best + 1 == ks.size())
    throw std::runtime_error("sliding dispersion: the growth is largest at the end of the scan in K");
  // Golden section on [K_{best-1}, K_{best+1}], Newton from the grid's root (the bracket is short).
  const Complex seed = roots[best];
  const auto scaled = [&](double K) { return K * newtonUpper(seed, mu, r, K).imag(); };
  double a = ks[best - 1], b = ks[best + 1];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = scaled(c), fd = scaled(d);
  for (int it = 0; it < 60 && b - a > 1e-10 * b; ++it) {
    if (fc > fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = scaled(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = scaled(d);
    }
  }
  return std::max({fc, fd, ks[best] * roots[best].imag()});
}

// The neutral Coulomb root against the sliding, on the real axis beyond -c_p/c_s (mu > 0): there
// alpha = i a, beta = i b (a, b > 0, the radiating limit) and D = -a eta^2 - mu (2 - eta^2 + 2 a b)
// is real, positive at -c_p/c_s (c_p^2 > 2 c_s^2) and ~ -r |eta|^3 far out. Bisection.
double againstSlidingNeutralRoot(double mu, double r) {
  const auto f = [mu, r](double x) { return dispersionUpper(Complex(x, 0.0), mu, r, 0.0).real(); };
  double near = -1.0 / r, far = 2.0 * near;
  while (f(far) > 0.0) far *= 2.0;
  for (int it = 0; it < 200 && near - far > 1e-15 * std::fabs(far); ++it) {
    const double middle = 0.5 * (near + far);
    (f(middle) > 0.0 ? near : far) = middle;
  }
  return 0.5 * (near + far);
}

}  // namespace

double shearToPressureSpeedRatio(double nu) { return std::sqrt((1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)); }

std::complex<double> slidingDispersion(std::complex<double> eta, double mu, double nu, int kSign, double memory) {
  checkArguments(nu, kSign);
  checkMemory(memory);
  const double r = shearToPressureSpeedRatio(nu);
  if (kSign > 0) return dispersionUpper(eta, mu, r, memory);
  return std::conj(dispersionUpper(std::conj(eta), mu, r, memory));  // k < 0: the conjugate problem
}

int countGrowingSlidingRoots(double mu, double nu, int kSign, double halfWidth, double memory) {
  checkArguments(nu, kSign);
  checkMemory(memory);
  const double r = shearToPressureSpeedRatio(nu);
  const double R = halfWidth > 0.0 ? halfWidth : enclosingHalfWidth(mu, r);
  // D / eta^2: the double root eta = 0 (a rigid shift) is divided out, and the contour may pass
  // next to it.
  if (kSign > 0) {
    const Function f = [mu, r, memory](Complex eta) { return reducedUpper(eta, mu, r, memory); };
    return windingNumber(f, {-R, R, kNeutralBand, R});
  }
  // k < 0: the lower half plane, counter-clockwise, with D_-(eta) = conj(D_+(conj eta)) evaluated
  // as such (the count checks the symmetry rather than assuming it).
  const Function f = [mu, r, memory](Complex eta) { return std::conj(reducedUpper(std::conj(eta), mu, r, memory)); };
  return windingNumber(f, {-R, R, -R, -kNeutralBand});
}

std::vector<SlidingMode> growingSlidingModes(double mu, double nu, double memory) {
  checkArguments(nu, 1);
  checkMemory(memory);
  const double r = shearToPressureSpeedRatio(nu);
  const double R = enclosingHalfWidth(mu, r);
  const Function f = [mu, r, memory](Complex eta) { return reducedUpper(eta, mu, r, memory); };
  const Box box{-R, R, kNeutralBand, R};
  const int n = windingNumber(f, box);
  std::vector<SlidingMode> modes;
  if (n <= 0) return modes;
  std::vector<Complex> roots;
  collectRoots(f, box, n, mu, r, memory, roots);
  std::sort(roots.begin(), roots.end(), [](Complex a, Complex b) { return a.imag() > b.imag(); });
  for (const Complex& root : roots) {
    if (!(root.imag() > 0.0)) continue;
    SlidingMode mode;
    mode.growing = true;
    mode.eta = root;
    mode.direction = root.real() > 0.0 ? 1 : -1;  // phase velocity c_s Re(eta) against +x, the sliding
    modes.push_back(mode);
  }
  return modes;
}

SlidingMode growingSlidingMode(double mu, double nu, double memory) {
  const std::vector<SlidingMode> modes = growingSlidingModes(mu, nu, memory);
  return modes.empty() ? SlidingMode{} : modes.front();
}

double slidingGrowthRate(double mu, double nu, double shearSpeed, double wavelength, double relaxationTime) {
  if (!(relaxationTime >= 0.0)) throw std::invalid_argument("slidingGrowthRate: the relaxation time must be >= 0");
  const double k = 2.0 * M_PI / wavelength;
  const SlidingMode mode = growingSlidingMode(mu, nu, k * shearSpeed * relaxationTime);
  if (!mode.growing) return 0.0;
  return 2.0 * M_PI / wavelength * shearSpeed * mode.eta.imag();
}

double memoryCutoff(double mu, double nu) {
  checkArguments(nu, 1);
  if (!(mu > 1.0)) return 0.0;
  // The flutter root reaches the real axis between c_s and c_p, where alpha and beta = -i b are
  // real and imaginary: Im D = 0 gives eta^2 = 2 mu b, eta^2 = 2 mu (mu - sqrt(mu^2 - 1)) (the root
  // below 2, as Re D = 0 needs), and Re D = 0 gives K = mu (2 - eta^2) / (alpha eta^3).
  const double r = shearToPressureSpeedRatio(nu);
  const double eta2 = 2.0 * mu / (mu + std::sqrt(mu * mu - 1.0));  // = 2 mu (mu - sqrt(mu^2 - 1)), no cancellation
  const double alpha = std::sqrt(1.0 - r * r * eta2);
  return mu * (2.0 - eta2) / (alpha * eta2 * std::sqrt(eta2));
}

double memoryCutoffWavelength(double mu, double nu, double shearSpeed, double relaxationTime) {
  const double K = memoryCutoff(mu, nu);
  return K > 0.0 ? 2.0 * M_PI * shearSpeed * relaxationTime / K : 0.0;
}

double memoryFlutterGrowth(double mu, double nu) {
  checkArguments(nu, 1);
  if (!(mu > 1.0)) return 0.0;
  const SlidingMode coulomb = growingSlidingMode(mu, nu);
  if (!coulomb.growing) return 0.0;
  return largestScaledGrowth(coulomb.eta, mu, shearToPressureSpeedRatio(nu), memoryCutoff(mu, nu));
}

double memoryModeGrowth(double mu, double nu) {
  checkArguments(nu, 1);
  if (!(mu > 0.0)) return 0.0;
  const double r = shearToPressureSpeedRatio(nu);
  return largestScaledGrowth(Complex(againstSlidingNeutralRoot(mu, r), 0.0), mu, r, 0.0);
}

}  // namespace gradfric
