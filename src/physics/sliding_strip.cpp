#include "gradfric/physics/sliding_strip.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace gradfric {

namespace {

constexpr double kPi = 3.14159265358979323846;

using ElementMatrix = std::array<std::array<double, 8>, 8>;

// The bilinear square of side h in plane strain (shear modulus 1), 2 x 2 Gauss points; dofs
// (x, z) of the corners (0,0), (1,0), (1,1), (0,1).
ElementMatrix squareStiffness(double h, double poisson) {
  const double lame = 2.0 * poisson / (1.0 - 2.0 * poisson), shear = 1.0;
  const double d[3][3] = {{lame + 2 * shear, lame, 0}, {lame, lame + 2 * shear, 0}, {0, 0, shear}};
  const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  ElementMatrix k{};
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      double b[3][8] = {};
      for (int a = 0; a < 4; ++a) {
        // d N_a / dx = (2 / h) d N_a / d xi on a square
        const double dx = corner[a][0] * (1 + corner[a][1] * eta) / 4 * (2 / h);
        const double dz = corner[a][1] * (1 + corner[a][0] * xi) / 4 * (2 / h);
        b[0][2 * a] = dx;
        b[1][2 * a + 1] = dz;
        b[2][2 * a] = dz;
        b[2][2 * a + 1] = dx;
      }
      const double weight = h * h / 4;
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          double s = 0;
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q) s += b[p][i] * d[p][q] * b[q][j];
          k[i][j] += s * weight;
        }
    }
  return k;
}

}  // namespace

SlidingStripHistory simulateSlidingStrip(const SlidingStripSettings& s) {
  if (!(s.poisson > -1 && s.poisson < 0.5) || s.elementsPerWavelength < 4 || !(s.depth > 0) || !(s.duration > 0) ||
      !(s.courant > 0 && s.courant < 1) || !(s.memory >= 0))
    throw std::invalid_argument("simulateSlidingStrip: settings out of range");
  const int nx = s.elementsPerWavelength, nz = static_cast<int>(std::lround(s.depth * nx));
  const double h = 1.0 / nx, k = 2 * kPi;
  const double pWave = std::sqrt(2.0 * (1 - s.poisson) / (1 - 2 * s.poisson));  // c_p / c_s
  const ElementMatrix ke = squareStiffness(h, s.poisson);
  const auto node = [nx](int i, int j) { return j * nx + ((i % nx) + nx) % nx; };
  const std::size_t nodes = static_cast<std::size_t>(nx) * (nz + 1);
  std::vector<double> ux(nodes), uz(nodes, 0.0), vx(nodes, 0.0), vz(nodes, 0.0), fx(nodes), fz(nodes), mass(nodes, h * h);
  for (int i = 0; i < nx; ++i) {
    mass[node(i, 0)] = mass[node(i, nz)] = h * h / 2;  // periodic along x: only the base and the top are edges
    for (int j = 0; j <= nz; ++j) ux[node(i, j)] = 1e-6 * std::cos(k * i * h) * std::exp(-k * j * h);
  }
  // The memory: R* per base node, relaxed toward R over each step exactly for R linear in time
  // between the previous and the current step's reactions (R* = R at t = 0).
  const bool memory = s.memory > 0;
  std::vector<double> relaxed(memory ? nx : 0), previous(memory ? nx : 0);
  double decay = 0, weightNew = 0, weightOld = 0;
  bool started = false;
  const auto forces = [&] {  // f = -K u, then the base's reaction and friction
    std::fill(fx.begin(), fx.end(), 0.0);
    std::fill(fz.begin(), fz.end(), 0.0);
    for (int j = 0; j < nz; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t n[4] = {static_cast<std::size_t>(node(i, j)), static_cast<std::size_t>(node(i + 1, j)),
                                  static_cast<std::size_t>(node(i + 1, j + 1)), static_cast<std::size_t>(node(i, j + 1))};
        double u[8];
        for (int a = 0; a < 4; ++a) {
          u[2 * a] = ux[n[a]];
          u[2 * a + 1] = uz[n[a]];
        }
        for (int a = 0; a < 4; ++a) {
          double gx = 0, gz = 0;
          for (int b = 0; b < 8; ++b) {
            gx += ke[2 * a][b] * u[b];
            gz += ke[2 * a + 1][b] * u[b];
          }
          fx[n[a]] -= gx;
          fz[n[a]] -= gz;
        }
      }
    for (int i = 0; i < nx; ++i) {  // the flat holds the base (R_z = -f_z); friction resists the sliding
      const std::size_t b = node(i, 0);
      const double reaction = -fz[b];
      fz[b] = 0;
      if (!memory) {
        fx[b] -= s.friction * reaction;
        continue;
      }
      // R*(t + dt) = e^-a R*(t) + (1 - (1 - e^-a)/a) R(t + dt) + ((1 - e^-a)/a - e^-a) R(t), a = dt/T
      relaxed[i] = started ? decay * relaxed[i] + weightNew * reaction + weightOld * previous[i] : reaction;
      previous[i] = reaction;
      fx[b] -= s.friction * relaxed[i];
    }
    started = true;
  };
  const auto record = [&](SlidingStripHistory& history, double t) {
    double re = 0, im = 0;
    for (int i = 0; i < nx; ++i) {
      re += ux[node(i, 0)] * std::cos(k * i * h);
      im -= ux[node(i, 0)] * std::sin(k * i * h);
    }
    double phase = std::atan2(im, re);
    if (!history.phase.empty())  // continuous: the step turns the phase by far less than pi
      phase += 2 * kPi * std::round((history.phase.back() - phase) / (2 * kPi));
    history.time.push_back(t);
    history.amplitude.push_back(std::hypot(re, im) / nx);
    history.phase.push_back(phase);
  };
  SlidingStripHistory history;
  history.step = s.courant * h / pWave;
  const long steps = static_cast<long>(std::ceil(s.duration / history.step));
  if (memory) {
    const double ratio = history.step / s.memory;
    decay = std::exp(-ratio);
    const double mean = -std::expm1(-ratio) / ratio;  // (1 - e^-a) / a
    weightNew = 1 - mean;
    weightOld = mean - decay;
  }
  forces();
  for (std::size_t n = 0; n < nodes; ++n) {  // v at the half step
    vx[n] = 0.5 * history.step * fx[n] / mass[n];
    vz[n] = 0.5 * history.step * fz[n] / mass[n];
  }
  record(history, 0.0);
  for (long step = 1; step <= steps; ++step) {
    for (std::size_t n = 0; n < nodes; ++n) {
      ux[n] += history.step * vx[n];
      uz[n] += history.step * vz[n];
    }
    forces();
    for (std::size_t n = 0; n < nodes; ++n) {
      vx[n] += history.step * fx[n] / mass[n];
      vz[n] += history.step * fz[n] / mass[n];
    }
    record(history, step * history.step);
  }
  return history;
}

namespace {

// The least-squares slope of values over time in [from, to].
double slopeOver(const std::vector<double>& time, const std::vector<double>& values, double from, double to) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double t = time[i], y = values[i];
    if (t < from || t > to || !std::isfinite(y)) continue;
    n += 1;
    st += t;
    sy += y;
    stt += t * t;
    sty += t * y;
  }
  if (n < 2) throw std::invalid_argument("sliding strip: fewer than two samples in the window");
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace

double fittedGrowthRate(const SlidingStripHistory& history, double from, double to) {
  std::vector<double> logs(history.amplitude.size());
  for (std::size_t i = 0; i < logs.size(); ++i)
    logs[i] = history.amplitude[i] > 0 ? std::log(history.amplitude[i]) : std::nan("");
  return slopeOver(history.time, logs, from, to);
}

double fittedPhaseSpeed(const SlidingStripHistory& history, double from, double to) {
  return -slopeOver(history.time, history.phase, from, to) / (2 * kPi);
}

std::array<FittedWave, 2> fittedWavePair(const SlidingStripHistory& history, double from, double to, double lag) {
  using Complex = std::complex<double>;
  if (!(history.step > 0) || !(lag > 0)) throw std::invalid_argument("sliding strip: no step or lag");
  const long L = std::max(1L, std::lround(lag / history.step));
  // Normal equations of min sum |a[n + 2L] - c1 a[n + L] - c0 a[n]|^2 (Hermitian 2 x 2).
  Complex m11 = 0, m12 = 0, m22 = 0, r1 = 0, r2 = 0;
  long samples = 0;
  const auto a = [&](std::size_t i) { return std::polar(history.amplitude[i], history.phase[i]); };
  for (std::size_t n = 0; n + 2 * L < history.time.size(); ++n) {
    if (history.time[n] < from || history.time[n + 2 * L] > to) continue;
    const Complex x0 = a(n), x1 = a(n + L), y = a(n + 2 * L);
    m11 += std::conj(x1) * x1, m12 += std::conj(x1) * x0, m22 += std::conj(x0) * x0;
    r1 += std::conj(x1) * y, r2 += std::conj(x0) * y;
    ++samples;
  }
  if (samples < 4) throw std::invalid_argument("sliding strip: too few samples for two waves in the window");
  const Complex det = m11 * m22 - m12 * std::conj(m12);
  const Complex c1 = (r1 * m22 - m12 * r2) / det, c0 = (m11 * r2 - std::conj(m12) * r1) / det;
  const Complex root = std::sqrt(c1 * c1 + 4.0 * c0);
  std::array<FittedWave, 2> waves;
  const double lagTime = L * history.step;
  for (int j = 0; j < 2; ++j) {
    const Complex z = 0.5 * (c1 + (j == 0 ? root : -root));
    const Complex s = std::log(z) / lagTime;
    waves[j].growthRate = s.real();
    waves[j].phaseSpeed = -s.imag() / (2 * kPi);
  }
  if (waves[0].phaseSpeed < waves[1].phaseSpeed) std::swap(waves[0], waves[1]);
  return waves;
}

}  // namespace gradfric
