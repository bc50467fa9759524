// The lattice is an isotropic elastic sheet: axial springs K_int = 3/4 E l_z and diagonals K_int/2
// give Young's modulus E and Poisson ratio 1/3 in every direction (plane stress). Measured with
// the model's own spring forces and virial stress under affine strains (exact for this lattice).
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

using Stress = std::array<double, 3>;  // sxx, syy, sxy

// Stress of an interior block under the affine displacement u = eps . x.
Stress stressUnder(const LatticeStiffness& s, double thickness, double exx, double eyy, double exy) {
  const int nb = s.blocksPerSide;
  std::vector<double> ux(nb * nb), uy(nb * nb);
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) {
      const double x = c * s.spacing, y = r * s.spacing;
      ux[r * nb + c] = exx * x + exy * y;
      uy[r * nb + c] = exy * x + eyy * y;
    }
  Stress stress;
  blockStress(s, thickness, ux.data(), uy.data(), nb / 2, nb / 2, stress.data());
  return stress;
}

// Compliance from the stiffness measured column by column (Voigt: exx, eyy, 2 exy).
std::array<std::array<double, 3>, 3> compliance(const LatticeStiffness& s, double thickness, double eps) {
  std::array<std::array<double, 3>, 3> C{};
  const Stress a = stressUnder(s, thickness, eps, 0, 0), b = stressUnder(s, thickness, 0, eps, 0),
               g = stressUnder(s, thickness, 0, 0, 0.5 * eps);
  for (int i = 0; i < 3; ++i) {
    C[i][0] = a[i] / eps;
    C[i][1] = b[i] / eps;
    C[i][2] = g[i] / eps;
  }
  // Invert the 3x3 matrix.
  const double det = C[0][0] * (C[1][1] * C[2][2] - C[1][2] * C[2][1]) - C[0][1] * (C[1][0] * C[2][2] - C[1][2] * C[2][0]) +
                     C[0][2] * (C[1][0] * C[2][1] - C[1][1] * C[2][0]);
  std::array<std::array<double, 3>, 3> S{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      S[i][j] = (C[i1][j1] * C[i2][j2] - C[i1][j2] * C[i2][j1]) / det;
    }
  return S;
}

// Young's modulus and Poisson ratio for uniaxial stress along the direction at angle theta.
void uniaxial(const std::array<std::array<double, 3>, 3>& S, double theta, double& modulus, double& poisson) {
  const double c = std::cos(theta), s = std::sin(theta);
  const std::array<double, 3> stress{c * c, s * s, c * s};  // unit uniaxial stress along n
  std::array<double, 3> strain{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) strain[i] += S[i][j] * stress[j];
  const double exx = strain[0], eyy = strain[1], exy = 0.5 * strain[2];
  const double along = exx * c * c + eyy * s * s + 2 * exy * c * s;
  const double across = exx * s * s + eyy * c * c - 2 * exy * c * s;
  modulus = 1.0 / along;
  poisson = -across / along;
}

}  // namespace

TEST(LatticeElasticity, IsotropicWithModulusEAndPoissonRatioOneThird) {
  Parameters p;
  p.blocksPerSide = 9;
  const LatticeStiffness s = buildStiffness(p, {});
  const auto S = compliance(s, p.layerThickness, 1e-5);
  for (double degrees : {0.0, 90.0, 45.0, 30.0}) {
    double modulus, poisson;
    uniaxial(S, degrees * M_PI / 180.0, modulus, poisson);
    EXPECT_NEAR(modulus, p.plate.youngsModulus, 0.01 * p.plate.youngsModulus) << degrees << " degrees";
    EXPECT_NEAR(poisson, 1.0 / 3.0, 0.02 / 3.0) << degrees << " degrees";
  }
}

TEST(LatticeElasticity, SnapshotStressIsTheContinuumStress) {
  // Uniaxial strain exx: sigma_x = E / (1 - nu^2) exx in plane stress; sigma_x / p as snapshots report.
  Parameters p;
  p.blocksPerSide = 7;
  const LatticeStiffness s = buildStiffness(p, {});
  const double exx = 2e-4;
  const int nb = p.blocksPerSide;
  std::vector<double> ux(nb * nb), uy(nb * nb, 0.0), sigma(nb * nb);
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) ux[r * nb + c] = exx * c * s.spacing;
  longitudinalStress(s, p.layerThickness, p.plate.pressure, ux.data(), uy.data(), sigma.data());
  const double expected = p.plate.youngsModulus / (1 - 1.0 / 9.0) * exx / p.plate.pressure;
  EXPECT_NEAR(sigma[3 * nb + 3], expected, 1e-3 * expected);
  // Tension is positive, compression negative.
  for (auto& u : ux) u = -u;
  longitudinalStress(s, p.layerThickness, p.plate.pressure, ux.data(), uy.data(), sigma.data());
  EXPECT_NEAR(sigma[3 * nb + 3], -expected, 1e-3 * expected);
}

TEST(LatticeElasticity, GradedSpringsTakeTheSeriesStiffness) {
  Parameters p;
  p.blocksPerSide = 10;
  Grading g;
  g.profile = GradingProfile::Linear;
  g.delta = 0.5;
  g.bands = 10;
  const LatticeStiffness s = buildStiffness(p, g);
  EXPECT_TRUE(s.graded);
  for (int c = 0; c + 1 < p.blocksPerSide; ++c) {
    const double a = s.vertical[c], b = s.vertical[c + 1];
    EXPECT_DOUBLE_EQ(s.horizontal[c], 2 * a * b / (a + b));
    EXPECT_DOUBLE_EQ(s.diagonal[c], a * b / (a + b));
  }
  // Column 0 is band 0: E = E0 (1 - Delta); the last column E0 (1 + Delta).
  EXPECT_DOUBLE_EQ(s.vertical.front(), 0.75 * p.plate.youngsModulus * 0.5 * p.layerThickness);
  EXPECT_DOUBLE_EQ(s.vertical.back(), 0.75 * p.plate.youngsModulus * 1.5 * p.layerThickness);
  EXPECT_DOUBLE_EQ(s.slider.back(), p.sliderStiffness(1.5 * p.plate.youngsModulus));
}
