// Pointwise FEM physics without PETSc: the box element and the contact return map.
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/hex_element.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

namespace {
double nodeCoord(int a, int axis, double h) { return ((a >> axis) & 1) * h; }
}  // namespace

TEST(FemElement, StiffnessIsSymmetricAndRigidModesAreFree) {
  const BoxElement e = makeBoxElement(50e-6, 40e-6, 10e-6, 1.0 / 3.0);
  double scale = 0;
  for (double k : e.stiffness) scale = std::max(scale, std::fabs(k));
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) EXPECT_NEAR(e.stiffness[i * 24 + j], e.stiffness[j * 24 + i], 1e-13 * scale);
  // Translations and an infinitesimal rotation give zero force.
  for (int mode = 0; mode < 4; ++mode) {
    double u[24];
    for (int a = 0; a < 8; ++a) {
      const double x = nodeCoord(a, 0, e.hx), y = nodeCoord(a, 1, e.hy);
      for (int c = 0; c < 3; ++c) u[3 * a + c] = mode < 3 ? (c == mode ? 1e-6 : 0.0) : 0.0;
      if (mode == 3) {  // rotation about z
        u[3 * a] = -y * 1e-3;
        u[3 * a + 1] = x * 1e-3;
      }
    }
    for (int i = 0; i < 24; ++i) {
      double f = 0;
      for (int j = 0; j < 24; ++j) f += e.stiffness[i * 24 + j] * u[j];
      EXPECT_NEAR(f, 0.0, 1e-12 * scale * 1e-6) << "mode " << mode << " row " << i;
    }
  }
}

TEST(FemElement, UniaxialStrainGivesTheExactTractionOnTheFace) {
  // u_x = eps x: the nodal forces on the x+ face sum to sigma_xx hy hz with sigma = (lambda + 2 mu) eps
  // when the lateral faces are held (plane strain is not imposed here: we check the element's
  // consistent forces against the analytic stress integral).
  const double nu = 0.25, E = 2.0;
  const BoxElement e = makeBoxElement(1.0, 2.0, 3.0, nu);
  const Lame l = lameFromYoung(E, nu);
  const double eps = 1e-3;
  double u[24] = {};
  for (int a = 0; a < 8; ++a) u[3 * a] = eps * nodeCoord(a, 0, e.hx);
  double fx = 0, fy = 0;
  for (int a = 0; a < 8; ++a) {
    if (!(a & 1)) continue;
    for (int j = 0; j < 24; ++j) {
      fx += E * e.stiffness[(3 * a) * 24 + j] * u[j];
      fy += E * e.stiffness[(3 * a + 1) * 24 + j] * u[j];
    }
  }
  EXPECT_NEAR(fx, (l.lambda + 2 * l.mu) * eps * e.hy * e.hz, 1e-12);
  const auto s = cellAverageStress(e, E, u);
  EXPECT_NEAR(s[0], (l.lambda + 2 * l.mu) * eps, 1e-15);
  EXPECT_NEAR(s[1], l.lambda * eps, 1e-15);
  EXPECT_NEAR(s[5], 0.0, 1e-15);
  // The face's y forces: sigma_xy = 0, and the lateral faces' sigma_yy shares cancel in the sum.
  EXPECT_NEAR(fy, 0.0, 1e-12);
}

TEST(FemElement, HighestFrequencyMatchesTheOneDimensionalLimit) {
  // A flat element: the highest frequency is a thickness mode, close to 2 c_p / hz per node pair
  // (lumped 1D bar: omega_max = 2 c / h). The element bound must not be below it.
  const double E = 10e6, nu = 1.0 / 3.0, rho = 1200;
  const BoxElement e = makeBoxElement(50e-6, 50e-6, 10e-6, nu);
  const Lame l = lameFromYoung(E, nu);
  const double cp = std::sqrt((l.lambda + 2 * l.mu) / rho);
  const double omega = std::sqrt(elementMaxFrequencySquared(e, E, rho));
  EXPECT_GE(omega, 2 * cp / e.hz * 0.999);
  EXPECT_LE(omega, 2 * cp / e.hz * 2.0);
  EXPECT_NEAR(centralDifferenceStableStep(4.0, 0.0), 1.0, 1e-15);
  EXPECT_LT(centralDifferenceStableStep(4.0, 0.1), 1.0);
}

TEST(FemContact, OpenStickAndSlip) {
  const PenaltyStiffness k{1e12, 2e12};
  const ExponentialVelocityWeakening law{{}, {SiteLayout::Uniform, 1, {1.0}, {0.6}}, 1e-4};
  // Open: no traction, anchor follows.
  auto r = penaltyContact(k, law, 0, 1e-9, 3e-9, 0, 0, 0, 0, 0, false);
  EXPECT_EQ(r.state, ContactState::Open);
  EXPECT_EQ(r.pressure, 0.0);
  EXPECT_EQ(r.anchorX, 3e-9);
  // Penetration 1e-8: pressure 1e4; small elastic slip sticks.
  r = penaltyContact(k, law, 0, -1e-8, 1e-9, 0, 0, 0, 0, 0, false);
  EXPECT_EQ(r.state, ContactState::Stick);
  EXPECT_DOUBLE_EQ(r.pressure, 1e4);
  EXPECT_DOUBLE_EQ(r.tx, -2e3);
  // Beyond mu_s p at rest: slips, traction on the cone opposite the displacement, anchor moved.
  r = penaltyContact(k, law, 0, -1e-8, 1e-8, 0, 0, 0, 0, 0, false);
  EXPECT_EQ(r.state, ContactState::Slip);
  EXPECT_NEAR(r.tx, -1e4, 1e-9);
  EXPECT_NEAR(-k.tangential * (1e-8 - r.anchorX), r.tx, 1e-9);
  // A sticking node moving fast (elastic motion) still holds up to mu_s p: slip rate zero.
  r = penaltyContact(k, law, 0, -1e-8, 0, 4.9e-9, 0, 0, 0, 1.0, false);
  EXPECT_EQ(r.state, ContactState::Stick);
  // Fast sliding: the cap falls to mu_k p (Eq. 1).
  r = penaltyContact(k, law, 0, -1e-8, 0, 1e-8, 0, 0, 0, 1.0, true);
  EXPECT_NEAR(r.ty, -0.6e4, 1e-6);
  // At v = v_c: mu = mu_k + (mu_s - mu_k)/e.
  r = penaltyContact(k, law, 0, -1e-8, 1e-8, 0, 0, 0, 1e-4, 0, true);
  EXPECT_NEAR(-r.tx, (0.6 + 0.4 * std::exp(-1.0)) * 1e4, 1e-6);
  // Returned state sticks on re-evaluation with the new anchor.
  auto again = penaltyContact(k, law, 0, -1e-8, 1e-8, 0, r.anchorX, r.anchorY, 0, 0, true);
  EXPECT_EQ(again.state, ContactState::Stick);
}
