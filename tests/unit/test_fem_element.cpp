// The incompatible-mode hexahedron (-fem_element q1i) against an independent reference: the
// condensation against a direct solve of the 33x33 element system built here a second way
// (B matrices on [-1, 1]^3, 3x3x3 Gauss points), the patch test, the rigid modes, pure bending
// reproduced exactly, and a slender cantilever with a tip load where plain Q1 locks.
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/incompatible_hex.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

// ---- The reference element: B-matrix form on the reference cube [-1, 1]^3 ----

// Shape-function gradients (physical) of the 8 corners and the 3 bubbles 1 - s^2.
void referenceGradients(double hx, double hy, double hz, double r, double s, double t, double g[11][3]) {
  const double h[3] = {hx, hy, hz}, p[3] = {r, s, t};
  for (int a = 0; a < 8; ++a) {
    double sign[3], value[3];
    for (int d = 0; d < 3; ++d) {
      sign[d] = ((a >> d) & 1) ? 1.0 : -1.0;
      value[d] = 0.5 * (1.0 + sign[d] * p[d]);
    }
    for (int d = 0; d < 3; ++d) {
      double v = 0.5 * sign[d] * 2.0 / h[d];  // dN/ds_d * ds_d/dx_d
      for (int e = 0; e < 3; ++e)
        if (e != d) v *= value[e];
      g[a][d] = v;
    }
  }
  for (int m = 0; m < 3; ++m)
    for (int d = 0; d < 3; ++d) g[8 + m][d] = d == m ? -2.0 * p[m] * 2.0 / h[m] : 0.0;
}

// The 33x33 stiffness (E = 1) as sum_q w_q B^T D B with the 6x33 strain matrix B.
std::vector<double> referenceStiffness33(double hx, double hy, double hz, double nu) {
  const double lambda = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1 / (2 * (1 + nu));
  double D[6][6] = {};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D[i][j] = lambda;
    D[i][i] += 2 * mu;
    D[3 + i][3 + i] = mu;
  }
  const double x3[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w3[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const double jacobian = hx * hy * hz / 8.0;
  std::vector<double> k(33 * 33, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l) {
        double g[11][3];
        referenceGradients(hx, hy, hz, x3[i], x3[j], x3[l], g);
        double B[6][33] = {};
        for (int f = 0; f < 11; ++f) {
          B[0][3 * f] = g[f][0];
          B[1][3 * f + 1] = g[f][1];
          B[2][3 * f + 2] = g[f][2];
          B[3][3 * f + 1] = g[f][2];  // gamma_yz
          B[3][3 * f + 2] = g[f][1];
          B[4][3 * f] = g[f][2];  // gamma_xz
          B[4][3 * f + 2] = g[f][0];
          B[5][3 * f] = g[f][1];  // gamma_xy
          B[5][3 * f + 1] = g[f][0];
        }
        const double w = w3[i] * w3[j] * w3[l] * jacobian;
        for (int p = 0; p < 33; ++p)
          for (int q = 0; q < 33; ++q) {
            double sum = 0;
            for (int m = 0; m < 6; ++m)
              for (int n = 0; n < 6; ++n) sum += B[m][p] * D[m][n] * B[n][q];
            k[p * 33 + q] += w * sum;
          }
      }
  return k;
}

// Dense Gaussian elimination with partial pivoting: solves A x = b (A n x n, overwritten).
std::vector<double> solveDense(std::vector<double> a, std::vector<double> b) {
  const int n = static_cast<int>(b.size());
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(a[r * n + c]) > std::fabs(a[pivot * n + c])) pivot = r;
    if (pivot != c) {
      for (int k = 0; k < n; ++k) std::swap(a[c * n + k], a[pivot * n + k]);
      std::swap(b[c], b[pivot]);
    }
    for (int r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      if (f == 0.0) continue;
      for (int k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (int r = n - 1; r >= 0; --r) {
    double sum = b[r];
    for (int k = r + 1; k < n; ++k) sum -= a[r * n + k] * x[k];
    x[r] = sum / a[r * n + r];
  }
  return x;
}

// Nodal forces of the reference element for nodal displacements ue: the 33x33 system with the
// 24 nodal dofs prescribed (rows replaced by identity) and zero force on the modes, solved
// directly; the forces are the nodal rows of K [ue; alpha].
std::vector<double> referenceNodalForces(const std::vector<double>& k33, const double* ue) {
  std::vector<double> a = k33, b(33, 0.0);
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 33; ++j) a[i * 33 + j] = i == j ? 1.0 : 0.0;
    b[i] = ue[i];
  }
  const std::vector<double> full = solveDense(a, b);
  std::vector<double> f(24, 0.0);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 33; ++j) f[i] += k33[i * 33 + j] * full[j];
  return f;
}

std::vector<double> applyStiffness(const std::array<double, 576>& k, const double* u) {
  std::vector<double> f(24, 0.0);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) f[i] += k[i * 24 + j] * u[j];
  return f;
}

double maxAbs(const std::array<double, 576>& k) {
  double m = 0;
  for (double v : k) m = std::max(m, std::fabs(v));
  return m;
}

double corner(int a, int axis, double h) { return ((a >> axis) & 1) * h; }

}  // namespace

TEST(FemIncompatibleElement, CondensationMatchesADirectSolveOfTheIndependent33x33System) {
  for (const double nu : {0.0, 1.0 / 3.0, 0.45}) {
    const double hx = 50e-6, hy = 40e-6, hz = 10e-6;
    const BoxElement e = makeBoxElement(hx, hy, hz, nu, ElementType::IncompatibleModes);
    EXPECT_EQ(e.type, ElementType::IncompatibleModes);
    // The 33x33 matrices of the two implementations agree.
    const std::vector<double> k33 = boxStiffness(hx, hy, hz, nu, true), ref33 = referenceStiffness33(hx, hy, hz, nu);
    double scale = 0;
    for (double v : ref33) scale = std::max(scale, std::fabs(v));
    for (int i = 0; i < 33 * 33; ++i) ASSERT_NEAR(k33[i], ref33[i], 1e-12 * scale) << "entry " << i << " nu " << nu;
    // Random nodal displacements: the condensed forces equal the reference's direct solve.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(-1e-6, 1e-6);
    for (int trial = 0; trial < 5; ++trial) {
      double u[24];
      for (double& v : u) v = uniform(rng);
      const std::vector<double> f = applyStiffness(e.stiffness, u), ref = referenceNodalForces(ref33, u);
      for (int i = 0; i < 24; ++i) EXPECT_NEAR(f[i], ref[i], 1e-11 * maxAbs(e.stiffness) * 1e-6) << "dof " << i;
      // The condensed forces are K_uu u + K_ua alpha with the energy-minimising mode amplitudes.
      const std::array<double, 9> alpha = incompatibleModeAmplitudes(k33, u);
      for (int i = 0; i < 24; ++i) {
        double sum = 0;
        for (int j = 0; j < 24; ++j) sum += k33[i * 33 + j] * u[j];
        for (int m = 0; m < 9; ++m) sum += k33[i * 33 + 24 + m] * alpha[m];
        EXPECT_NEAR(f[i], sum, 1e-11 * maxAbs(e.stiffness) * 1e-6);
      }
    }
    // Exactly symmetric (the kernel reads rows as columns), and softer than Q1: K_q1 - K_q1i is
    // positive semi-definite, so u . K_q1i u <= u . K_q1 u.
    const BoxElement q1 = makeBoxElement(hx, hy, hz, nu);
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j) ASSERT_EQ(e.stiffness[i * 24 + j], e.stiffness[j * 24 + i]);
    double u[24];
    for (double& v : u) v = uniform(rng);
    const std::vector<double> fi = applyStiffness(e.stiffness, u), fq = applyStiffness(q1.stiffness, u);
    double ei = 0, eq = 0;
    for (int i = 0; i < 24; ++i) {
      ei += u[i] * fi[i];
      eq += u[i] * fq[i];
    }
    EXPECT_LE(ei, eq * (1 + 1e-12));
    EXPECT_GT(ei, 0.0);
  }
}

TEST(FemIncompatibleElement, PatchTestAndRigidModes) {
  const double hx = 50e-6, hy = 40e-6, hz = 10e-6, nu = 1.0 / 3.0;
  const BoxElement e = makeBoxElement(hx, hy, hz, nu, ElementType::IncompatibleModes);
  const BoxElement q1 = makeBoxElement(hx, hy, hz, nu);
  const double scale = maxAbs(e.stiffness);
  // Six rigid modes (three translations, three infinitesimal rotations) give zero force.
  for (int mode = 0; mode < 6; ++mode) {
    double u[24];
    for (int a = 0; a < 8; ++a) {
      const double x[3] = {corner(a, 0, hx), corner(a, 1, hy), corner(a, 2, hz)};
      for (int c = 0; c < 3; ++c) u[3 * a + c] = mode < 3 ? (c == mode ? 1e-6 : 0.0) : 0.0;
      if (mode >= 3) {  // rotation about axis mode - 3: u = w x r with |w| = 1e-3
        const int i = (mode - 3 + 1) % 3, j = (mode - 3 + 2) % 3;
        u[3 * a + i] = -1e-3 * x[j];
        u[3 * a + j] = 1e-3 * x[i];
      }
    }
    const std::vector<double> f = applyStiffness(e.stiffness, u);
    for (int i = 0; i < 24; ++i) EXPECT_NEAR(f[i], 0.0, 1e-12 * scale * 1e-6) << "mode " << mode << " dof " << i;
  }
  // Constant strain (a general linear field): the modes stay at rest, the nodal forces are Q1's
  // (the consistent forces of the constant stress), and the cell stress is the exact one.
  const double grad[3][3] = {{1e-3, 2e-4, -3e-4}, {5e-4, -7e-4, 1e-4}, {-2e-4, 6e-4, 4e-4}};
  double u[24];
  for (int a = 0; a < 8; ++a) {
    const double x[3] = {corner(a, 0, hx), corner(a, 1, hy), corner(a, 2, hz)};
    for (int c = 0; c < 3; ++c) u[3 * a + c] = grad[c][0] * x[0] + grad[c][1] * x[1] + grad[c][2] * x[2];
  }
  const std::array<double, 9> alpha = incompatibleModeAmplitudes(boxStiffness(hx, hy, hz, nu, true), u);
  for (int m = 0; m < 9; ++m) EXPECT_NEAR(alpha[m], 0.0, 1e-15) << "mode " << m;
  const std::vector<double> fi = applyStiffness(e.stiffness, u), fq = applyStiffness(q1.stiffness, u);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(fi[i], fq[i], 1e-12 * scale * 1e-3);
  const Lame l = lameFromYoung(1.0, nu);
  const double tr = grad[0][0] + grad[1][1] + grad[2][2];
  const auto s = cellAverageStress(e, 1.0, u);
  EXPECT_NEAR(s[0], l.lambda * tr + 2 * l.mu * grad[0][0], 1e-15);
  EXPECT_NEAR(s[4], l.mu * (grad[0][2] + grad[2][0]), 1e-15);
}

namespace {

// A clamped beam of box cells, assembled densely: length lx, width ly, height lz on nx x ny x nz
// cells, every dof of the x = 0 face fixed, nodal loads from load(node index i, j, k) in z.
// Returns the mean z displacement of the x = lx face.
double beamTipDeflection(ElementType type, double lx, double ly, double lz, int nx, int ny, int nz, double E, double nu,
                         const std::function<double(int, int, int, double)>& zLoad,
                         const std::function<double(int, int, int, double)>& xLoad) {
  const BoxElement e = makeBoxElement(lx / nx, ly / ny, lz / nz, nu, type);
  const int px = nx + 1, py = ny + 1, pz = nz + 1;
  // Free dofs: nodes with i >= 1.
  auto dof = [&](int i, int j, int k, int c) { return 3 * ((i - 1) + nx * (j + py * k)) + c; };
  const int n = 3 * nx * py * pz;
  std::vector<double> K(static_cast<size_t>(n) * n, 0.0), f(n, 0.0);
  for (int ci = 0; ci < nx; ++ci)
    for (int cj = 0; cj < ny; ++cj)
      for (int ck = 0; ck < nz; ++ck)
        for (int a = 0; a < 8; ++a)
          for (int b = 0; b < 8; ++b) {
            const int ia = ci + (a & 1), ja = cj + ((a >> 1) & 1), ka = ck + ((a >> 2) & 1);
            const int ib = ci + (b & 1), jb = cj + ((b >> 1) & 1), kb = ck + ((b >> 2) & 1);
            if (ia == 0 || ib == 0) continue;
            for (int c = 0; c < 3; ++c)
              for (int d = 0; d < 3; ++d)
                K[static_cast<size_t>(dof(ia, ja, ka, c)) * n + dof(ib, jb, kb, d)] +=
                    E * e.stiffness[(3 * a + c) * 24 + 3 * b + d];
          }
  for (int i = 1; i < px; ++i)
    for (int j = 0; j < py; ++j)
      for (int k = 0; k < pz; ++k) {
        const double z = k * lz / nz;
        f[dof(i, j, k, 2)] += zLoad(i, j, k, z);
        f[dof(i, j, k, 0)] += xLoad(i, j, k, z);
      }
  const std::vector<double> u = solveDense(K, f);
  double sum = 0;
  for (int j = 0; j < py; ++j)
    for (int k = 0; k < pz; ++k) sum += u[dof(nx, j, k, 2)];
  return sum / (py * pz);
}

// Consistent nodal share of a uniform traction on the end face x = lx: the bilinear face's
// tributary area of node (j, k).
double endFaceShare(int j, int k, int ny, int nz) {
  const double wy = (j == 0 || j == ny) ? 0.5 : 1.0, wz = (k == 0 || k == nz) ? 0.5 : 1.0;
  return wy * wz / (ny * nz);
}

}  // namespace

TEST(FemIncompatibleElement, PureBendingIsExactWherePlainQ1Locks) {
  // End moment M as the linear traction sigma_xx = -M (z - h/2) / I on the end face; nu = 0, so
  // the fully clamped root imposes nothing the beam solution violates: tip w = M L^2 / (2 E I).
  const double L = 1.0, b = 0.1, h = 0.05, E = 1e7, M = 1.0, I = b * h * h * h / 12;
  const int nx = 10, ny = 1, nz = 2;
  auto xLoad = [&](int i, int j, int k, double) {
    if (i != nx) return 0.0;
    // The consistent nodal loads of the linear traction on the face (per column of nodes in z).
    const double hz = h / nz, sigmaSlope = -M / I, wy = (j == 0 || j == ny) ? 0.5 * b / ny : b / ny;
    auto traction = [&](double z) { return sigmaSlope * (z - h / 2); };
    double share = 0;
    if (k > 0) share += hz * (traction((k - 1) * hz) / 6 + traction(k * hz) / 3);
    if (k < nz) share += hz * (traction(k * hz) / 3 + traction((k + 1) * hz) / 6);
    return wy * share;
  };
  auto none = [](int, int, int, double) { return 0.0; };
  const double exact = M * L * L / (2 * E * I);
  const double wi = beamTipDeflection(ElementType::IncompatibleModes, L, b, h, nx, ny, nz, E, 0.0, none, xLoad);
  const double wq = beamTipDeflection(ElementType::Trilinear, L, b, h, nx, ny, nz, E, 0.0, none, xLoad);
  // Q1's parasitic shear gamma_xz = kappa (x - x_c) adds G kappa^2 hx^2 / 12 per unit volume to
  // the bending energy E kappa^2 h^2 / 12 (nu = 0): the beam is 1 + (G/E)(hx/h)^2 times too stiff.
  const double q1Locking = 1.0 / (1.0 + 0.5 * (L / nx / h) * (L / nx / h));
  std::printf("pure bending L/h = 20, %d x %d x %d cells: tip w / exact: q1i %.8f, q1 %.6f (locking prediction %.6f)\n",
              nx, ny, nz, wi / exact, wq / exact, q1Locking);
  EXPECT_NEAR(wi / exact, 1.0, 1e-8);
  EXPECT_NEAR(wq / exact, q1Locking, 1e-6);
  EXPECT_LT(wq / exact, 0.34);
}

TEST(FemIncompatibleElement, SlenderCantileverTipLoadMatchesBeamTheoryWherePlainQ1Locks) {
  // Tip load P (uniform shear traction on the end face), nu = 0: Timoshenko's tip deflection
  // P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6.
  const double L = 1.0, b = 0.1, h = 0.05, E = 1e7, P = 1.0, I = b * h * h * h / 12, G = E / 2;
  const double exact = P * L * L * L / (3 * E * I) + P * L / (5.0 / 6.0 * G * b * h);
  auto none = [](int, int, int, double) { return 0.0; };
  struct Mesh {
    int nx, ny, nz;
  };
  for (const Mesh m : {Mesh{10, 1, 2}, Mesh{20, 1, 1}, Mesh{40, 1, 4}}) {
    auto zLoad = [&](int i, int j, int k, double) { return i == m.nx ? P * endFaceShare(j, k, m.ny, m.nz) : 0.0; };
    const double wi = beamTipDeflection(ElementType::IncompatibleModes, L, b, h, m.nx, m.ny, m.nz, E, 0.0, zLoad, none);
    const double wq = beamTipDeflection(ElementType::Trilinear, L, b, h, m.nx, m.ny, m.nz, E, 0.0, zLoad, none);
    const double q1Locking = 1.0 / (1.0 + 0.5 * (L / m.nx / h) * (L / m.nx / h));  // as in pure bending
    std::printf("cantilever L/h = 20, %d x %d x %d cells (hx/h %.2f): tip w / Timoshenko: q1i %.5f (error %+.2f %%), "
                "q1 %.5f (error %+.1f %%, locking prediction %.4f)\n",
                m.nx, m.ny, m.nz, L / m.nx / h, wi / exact, 100 * (wi / exact - 1), wq / exact, 100 * (wq / exact - 1),
                q1Locking);
    EXPECT_NEAR(wi / exact, 1.0, 0.01);
    EXPECT_NEAR(wq / exact, q1Locking, 0.01);
    EXPECT_LT(wq / exact, 0.9);
  }
}
