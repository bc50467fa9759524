#include "gradfric/fem/hex_element.hpp"

#include "gradfric/fem/incompatible_hex.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

Lame lameFromYoung(double E, double nu) {
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

const char* elementTypeName(ElementType type) { return type == ElementType::Trilinear ? "q1" : "q1i"; }

namespace {

// Gradients of the 8 trilinear shape functions at reference point (xi, eta, zeta) in [0, 1]^3,
// mapped to the box (physical derivatives), then those of the 3 bubbles 4 s (1 - s).
void shapeGradients(double hx, double hy, double hz, double xi, double eta, double zeta, double grad[11][3]) {
  for (int a = 0; a < 8; ++a) {
    const int i = a & 1, j = (a >> 1) & 1, k = (a >> 2) & 1;
    const double nx = i ? xi : 1 - xi, ny = j ? eta : 1 - eta, nz = k ? zeta : 1 - zeta;
    const double dx = i ? 1.0 : -1.0, dy = j ? 1.0 : -1.0, dz = k ? 1.0 : -1.0;
    grad[a][0] = dx * ny * nz / hx;
    grad[a][1] = nx * dy * nz / hy;
    grad[a][2] = nx * ny * dz / hz;
  }
  const double s[3] = {xi, eta, zeta}, h[3] = {hx, hy, hz};
  for (int m = 0; m < 3; ++m)
    for (int d = 0; d < 3; ++d) grad[8 + m][d] = d == m ? 4.0 * (1.0 - 2.0 * s[m]) / h[m] : 0.0;
}

}  // namespace

std::vector<double> boxStiffness(double hx, double hy, double hz, double nu, bool withBubbles) {
  const int shapes = withBubbles ? 11 : 8, n = 3 * shapes;
  std::vector<double> k(n * n, 0.0);
  const Lame lame = lameFromYoung(1.0, nu);
  const double g = 0.5 / std::sqrt(3.0);
  const double pts[2] = {0.5 - g, 0.5 + g};
  const double weight = hx * hy * hz / 8.0;
  for (double xi : pts)
    for (double eta : pts)
      for (double zeta : pts) {
        double grad[11][3];
        shapeGradients(hx, hy, hz, xi, eta, zeta, grad);
        for (int a = 0; a < shapes; ++a)
          for (int b = 0; b < shapes; ++b) {
            const double dot = grad[a][0] * grad[b][0] + grad[a][1] * grad[b][1] + grad[a][2] * grad[b][2];
            for (int c = 0; c < 3; ++c)
              for (int d = 0; d < 3; ++d) {
                double kk = lame.lambda * grad[a][c] * grad[b][d] + lame.mu * grad[a][d] * grad[b][c];
                if (c == d) kk += lame.mu * dot;
                k[(3 * a + c) * n + 3 * b + d] += weight * kk;
              }
          }
      }
  return k;
}

BoxElement makeBoxElement(double hx, double hy, double hz, double nu, ElementType type) {
  BoxElement e;
  e.hx = hx;
  e.hy = hy;
  e.hz = hz;
  e.poissonRatio = nu;
  e.type = type;
  if (type == ElementType::IncompatibleModes) {
    e.stiffness = condenseIncompatibleModes(boxStiffness(hx, hy, hz, nu, true));
  } else {
    const std::vector<double> k = boxStiffness(hx, hy, hz, nu, false);
    std::copy(k.begin(), k.end(), e.stiffness.begin());
  }
  return e;
}

double largestEigenvalue(const std::array<double, 24 * 24>& matrix) {
  constexpr int n = 24;
  std::array<double, n * n> a = matrix;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (int p = 0; p < n; ++p)
      for (int q = 0; q < n; ++q) (p == q ? diag : off) += a[p * n + q] * a[p * n + q];
    if (off <= 1e-30 * diag) break;
    for (int p = 0; p < n - 1; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (std::fabs(apq) < 1e-300) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) {  // columns p, q
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq;
          a[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // rows p, q
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk;
          a[q * n + k] = s * apk + c * aqk;
        }
      }
  }
  double largest = a[0];
  for (int p = 1; p < n; ++p) largest = std::max(largest, a[p * n + p]);
  return largest;
}

double elementMaxFrequencySquared(const BoxElement& element, double E, double rho) {
  const double nodeMass = rho * element.volume() / 8.0;
  return E * largestEigenvalue(element.stiffness) / nodeMass;
}

double centralDifferenceStableStep(double omegaSquared, double xi) {
  const double omega = std::sqrt(omegaSquared);
  return 2.0 / omega * (std::sqrt(1.0 + xi * xi) - xi);
}

std::array<double, 6> cellAverageStress(const BoxElement& e, double E, const double* ue) {
  double grad[11][3];
  shapeGradients(e.hx, e.hy, e.hz, 0.5, 0.5, 0.5, grad);  // the centroid: the mean gradient of a box cell
  double du[3][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) du[c][d] += ue[3 * a + c] * grad[a][d];
  const Lame l = lameFromYoung(E, e.poissonRatio);
  const double tr = du[0][0] + du[1][1] + du[2][2];
  return {l.lambda * tr + 2 * l.mu * du[0][0], l.lambda * tr + 2 * l.mu * du[1][1], l.lambda * tr + 2 * l.mu * du[2][2],
          l.mu * (du[1][2] + du[2][1]),       l.mu * (du[0][2] + du[2][0]),       l.mu * (du[0][1] + du[1][0])};
}

}  // namespace gradfric::fem
