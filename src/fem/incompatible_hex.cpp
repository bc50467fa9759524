// Static condensation of the incompatible modes (incompatible_hex.hpp): a Cholesky factor of the
// 9x9 mode block, solved against the 24 nodal columns once per element shape.
#include "gradfric/fem/incompatible_hex.hpp"

#include <cmath>
#include <stdexcept>

namespace gradfric::fem {

namespace {

constexpr int kNodal = 24, kModes = 9, kAll = 33;

// Lower Cholesky factor of the SPD mode block K_aa (9x9, row-major).
std::array<double, kModes * kModes> modeBlockFactor(const std::vector<double>& k) {
  if (k.size() != static_cast<size_t>(kAll * kAll))
    throw std::invalid_argument("incompatible modes: the stiffness must be 33x33");
  std::array<double, kModes * kModes> l{};
  for (int i = 0; i < kModes; ++i)
    for (int j = 0; j <= i; ++j) {
      double sum = k[(kNodal + i) * kAll + kNodal + j];
      for (int p = 0; p < j; ++p) sum -= l[i * kModes + p] * l[j * kModes + p];
      if (i == j) {
        if (!(sum > 0)) throw std::runtime_error("incompatible modes: the mode stiffness is not positive definite");
        l[i * kModes + i] = std::sqrt(sum);
      } else {
        l[i * kModes + j] = sum / l[j * kModes + j];
      }
    }
  return l;
}

// Solves L L^T x = b in place.
void choleskySolve(const std::array<double, kModes * kModes>& l, double* b) {
  for (int i = 0; i < kModes; ++i) {
    for (int p = 0; p < i; ++p) b[i] -= l[i * kModes + p] * b[p];
    b[i] /= l[i * kModes + i];
  }
  for (int i = kModes - 1; i >= 0; --i) {
    for (int p = i + 1; p < kModes; ++p) b[i] -= l[p * kModes + i] * b[p];
    b[i] /= l[i * kModes + i];
  }
}

}  // namespace

std::array<double, 24 * 24> condenseIncompatibleModes(const std::vector<double>& k) {
  const auto l = modeBlockFactor(k);
  // X = K_aa^-1 K_au, one nodal column at a time.
  std::array<double, kModes * kNodal> x{};
  for (int j = 0; j < kNodal; ++j) {
    double column[kModes];
    for (int m = 0; m < kModes; ++m) column[m] = k[(kNodal + m) * kAll + j];
    choleskySolve(l, column);
    for (int m = 0; m < kModes; ++m) x[m * kNodal + j] = column[m];
  }
  std::array<double, 24 * 24> condensed{};
  for (int i = 0; i < kNodal; ++i)
    for (int j = 0; j < kNodal; ++j) {
      double sum = k[i * kAll + j];
      for (int m = 0; m < kModes; ++m) sum -= k[i * kAll + kNodal + m] * x[m * kNodal + j];
      condensed[i * kNodal + j] = sum;
    }
  // The kernel reads rows as columns: make the symmetry exact, not only up to round-off.
  for (int i = 0; i < kNodal; ++i)
    for (int j = i + 1; j < kNodal; ++j) {
      const double mean = 0.5 * (condensed[i * kNodal + j] + condensed[j * kNodal + i]);
      condensed[i * kNodal + j] = condensed[j * kNodal + i] = mean;
    }
  return condensed;
}

std::array<double, 9> incompatibleModeAmplitudes(const std::vector<double>& k, const double* ue) {
  const auto l = modeBlockFactor(k);
  std::array<double, kModes> alpha{};
  for (int m = 0; m < kModes; ++m) {
    double sum = 0;
    for (int j = 0; j < kNodal; ++j) sum += k[(kNodal + m) * kAll + j] * ue[j];
    alpha[m] = -sum;
  }
  choleskySolve(l, alpha.data());
  return alpha;
}

}  // namespace gradfric::fem
