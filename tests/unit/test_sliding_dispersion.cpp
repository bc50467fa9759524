// The plane-strain dispersion relation of a half-space sliding on a rigid flat with constant mu
// (docs/flutter.md): the neutral root at mu = 1, the count of growing roots, the notes' values at
// nu = 1/3, the growth rate, and the root against an independent 2 x 2 boundary determinant.
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/sliding_dispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

using namespace gradfric;
using Complex = std::complex<double>;

namespace {

const std::vector<double> kPoisson{0.05, 0.25, 1.0 / 3.0, 0.45, 0.49};

// The project's plate: c_s = sqrt(G / rho) = sqrt(3.75e6 Pa / 1200 kg/m^3) = 55.90 m/s.
double plateShearSpeed() {
  const Plate plate;
  return std::sqrt(plate.shearModulus() / plate.density);
}

// The boundary conditions built directly from the potentials, not from the closed form: k = 1,
// rho = c_s = 1, phi = A exp(i x - a z), psi = B exp(i x - b z) with the decaying roots of the
// wave equations a^2 = 1 - eta^2 c_s^2/c_p^2, b^2 = 1 - eta^2 (principal sqrt: Re > 0 off the real
// axis). u_x = phi_x - psi_z, u_z = phi_z + psi_x; sigma_zz = lambda div u + 2 G u_z,z,
// sigma_xz = G (u_x,z + u_z,x). The flat pushes the body with t_z = -sigma_zz = p > 0 and the
// friction opposes the +x sliding: t_x = -sigma_xz = -mu p. Rows: u_z = 0, sigma_xz + mu sigma_zz = 0.
Complex boundaryDeterminant(Complex eta, double mu, double nu) {
  const double G = 1.0;
  const double cp2 = (2.0 - 2.0 * nu) / (1.0 - 2.0 * nu);
  const double lambda = cp2 - 2.0 * G;
  const Complex i(0.0, 1.0);
  const Complex a = std::sqrt(1.0 - eta * eta / cp2), b = std::sqrt(1.0 - eta * eta);
  // d/dx and d/dz of each potential's exponential.
  const Complex dxP = i, dzP = -a, dxS = i, dzS = -b;
  // Displacement per unit amplitude of each potential, then its x and z derivatives.
  const Complex uxA = dxP, uzA = dzP;   // grad phi
  const Complex uxB = -dzS, uzB = dxS;  // curl (psi e_y)
  auto sigmaZZ = [&](Complex ux, Complex uz, Complex dx, Complex dz) {
    return lambda * (dx * ux + dz * uz) + 2.0 * G * dz * uz;
  };
  auto sigmaXZ = [&](Complex ux, Complex uz, Complex dx, Complex dz) { return G * (dz * ux + dx * uz); };
  const Complex m11 = uzA, m12 = uzB;
  const Complex m21 = sigmaXZ(uxA, uzA, dxP, dzP) + mu * sigmaZZ(uxA, uzA, dxP, dzP);
  const Complex m22 = sigmaXZ(uxB, uzB, dxS, dzS) + mu * sigmaZZ(uxB, uzB, dxS, dzS);
  return m11 * m22 - m12 * m21;
}

// Its growing root by a method of its own: the smallest |det / eta^2| on a grid over the upper
// half plane, then the secant method.
Complex determinantRoot(double mu, double nu) {
  Complex best(1.0, 0.1);
  double bestValue = INFINITY;
  for (int ix = 0; ix <= 300; ++ix) {
    for (int iy = 1; iy <= 200; ++iy) {
      const Complex eta(0.1 + 2.9 * ix / 300.0, 0.8 * iy / 200.0);
      const double value = std::abs(boundaryDeterminant(eta, mu, nu) / (eta * eta));
      if (value < bestValue) bestValue = value, best = eta;
    }
  }
  Complex x0 = best, x1 = best + Complex(1e-3, 1e-3);
  Complex f0 = boundaryDeterminant(x0, mu, nu), f1 = boundaryDeterminant(x1, mu, nu);
  for (int it = 0; it < 100 && std::abs(x1 - x0) > 1e-15 && f1 != f0; ++it) {
    const Complex x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1, x1 = x2, f1 = boundaryDeterminant(x1, mu, nu);
  }
  return x1;
}

}  // namespace

TEST(SlidingDispersion, NeutralRootAtMuOneIsSqrtTwoForEveryNu) {
  for (double nu : kPoisson) {
    EXPECT_LT(std::abs(slidingDispersion(std::sqrt(2.0), 1.0, nu)), 1e-14) << "nu " << nu;
    EXPECT_FALSE(growingSlidingMode(1.0, nu).growing) << "nu " << nu;  // on the axis: neutral
    const SlidingMode justAbove = growingSlidingMode(1.0 + 1e-6, nu);  // the root leaves the axis there
    ASSERT_TRUE(justAbove.growing) << "nu " << nu;
    EXPECT_NEAR(justAbove.eta.real(), std::sqrt(2.0), 1e-5) << "nu " << nu;
    EXPECT_GT(justAbove.eta.imag(), 0.0);
    EXPECT_LT(justAbove.eta.imag(), 1e-5);
  }
}

TEST(SlidingDispersion, NoGrowingRootUpToMuOneInEitherDirection) {
  for (double nu : kPoisson) {
    for (double mu : {0.5, 0.9, 1.0}) {
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, +1), 0) << "mu " << mu << " nu " << nu;
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, -1), 0) << "mu " << mu << " nu " << nu;
      EXPECT_FALSE(growingSlidingMode(mu, nu).growing);
      EXPECT_EQ(slidingGrowthRate(mu, nu, plateShearSpeed(), 25e-6), 0.0);
    }
  }
}

// Exactly one above mu = 1, for k > 0 and k < 0 alike (the k < 0 roots are the conjugates), and
// the same on a contour of half-width 500. The exception: at nu = 0.05 the root has gone back
// to the real axis, beyond c_p, at mu ~ 1.785, so mu = 2 has none (docs/flutter.md).
TEST(SlidingDispersion, ExactlyOneGrowingRootAboveMuOne) {
  for (double nu : kPoisson) {
    for (double mu : {1.1, 1.2, 1.4, 2.0}) {
      const int expected = (nu == 0.05 && mu == 2.0) ? 0 : 1;
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, +1), expected) << "mu " << mu << " nu " << nu;
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, -1), expected) << "mu " << mu << " nu " << nu;
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, +1, 500.0), expected);  // a far larger contour
      EXPECT_EQ(growingSlidingMode(mu, nu).growing, expected == 1);
    }
  }
  EXPECT_EQ(countGrowingSlidingRoots(1.78, 0.05), 1);
  EXPECT_EQ(countGrowingSlidingRoots(1.80, 0.05), 0);
}

TEST(SlidingDispersion, RootSolvesTheRelationAndTravelsWithTheSliding) {
  for (double nu : kPoisson) {
    for (double mu : {1.01, 1.1, 1.2, 1.4, 1.7, 2.0}) {
      const SlidingMode mode = growingSlidingMode(mu, nu);
      if (!mode.growing) continue;  // nu = 0.05, mu = 2 (above)
      EXPECT_LT(std::abs(slidingDispersion(mode.eta, mu, nu)), 1e-10) << "mu " << mu << " nu " << nu;
      EXPECT_GT(mode.eta.imag(), 0.0);
      EXPECT_GT(mode.eta.real(), 1.0);  // faster than c_s, in +x
      EXPECT_EQ(mode.direction, 1);
      // k < 0: the conjugate root, the same wave (phase velocity c_s Re(eta) > 0).
      EXPECT_LT(std::abs(slidingDispersion(std::conj(mode.eta), mu, nu, -1)), 1e-10);
    }
  }
}

// The note: eta ~ 1.41 + 0.088i (mu 1.2), 1.41 + 0.159i (mu 1.4) at nu = 1/3, and e-folding times
// 0.8 us and 0.45 us at lambda = 25 um with the plate's c_s.
TEST(SlidingDispersion, MatchesTheNotesValuesAtNuOneThird) {
  const SlidingMode at12 = growingSlidingMode(1.2, 1.0 / 3.0);
  const SlidingMode at14 = growingSlidingMode(1.4, 1.0 / 3.0);
  ASSERT_TRUE(at12.growing && at14.growing);
  EXPECT_NEAR(at12.eta.real(), 1.41, 0.005);
  EXPECT_NEAR(at12.eta.imag(), 0.088, 0.0005);
  EXPECT_NEAR(at14.eta.real(), 1.41, 0.005);
  EXPECT_NEAR(at14.eta.imag(), 0.159, 0.0005);
  const double cs = plateShearSpeed();
  EXPECT_NEAR(cs, 55.9017, 1e-4);
  EXPECT_NEAR(1.0 / slidingGrowthRate(1.2, 1.0 / 3.0, cs, 25e-6), 0.8e-6, 0.05e-6);
  EXPECT_NEAR(1.0 / slidingGrowthRate(1.4, 1.0 / 3.0, cs, 25e-6), 0.45e-6, 0.005e-6);
}

TEST(SlidingDispersion, GrowthRateIsLinearInTheWavenumber) {
  const double cs = plateShearSpeed();
  const double reference = slidingGrowthRate(1.2, 1.0 / 3.0, cs, 25e-6);
  EXPECT_NEAR(reference, 2.0 * M_PI / 25e-6 * cs * growingSlidingMode(1.2, 1.0 / 3.0).eta.imag(), 1e-9 * reference);
  for (double wavelength : {1e-6, 5e-6, 100e-6, 1e-3})
    EXPECT_NEAR(slidingGrowthRate(1.2, 1.0 / 3.0, cs, wavelength) * wavelength, reference * 25e-6,
                1e-9 * reference * 25e-6);
}

// Monotonic in mu where the root stays in the upper half plane up to mu = 2 (nu >= 0.11); at
// nu = 0.05 it peaks (mu ~ 1.5) and returns to the axis.
TEST(SlidingDispersion, GrowthRisesMonotonicallyWithMu) {
  for (double nu : {0.25, 1.0 / 3.0, 0.45, 0.49}) {
    double previous = 0.0;
    for (double mu = 1.05; mu <= 2.0 + 1e-9; mu += 0.05) {
      const SlidingMode mode = growingSlidingMode(mu, nu);
      ASSERT_TRUE(mode.growing) << "mu " << mu << " nu " << nu;
      EXPECT_GT(mode.eta.imag(), previous) << "mu " << mu << " nu " << nu;
      previous = mode.eta.imag();
    }
  }
  EXPECT_GT(growingSlidingMode(1.5, 0.05).eta.imag(), growingSlidingMode(1.75, 0.05).eta.imag());
}

TEST(SlidingDispersion, RootMatchesAnIndependentBoundaryDeterminant) {
  for (double nu : kPoisson) {
    for (double mu : {1.1, 1.2, 1.4, 1.7}) {
      const SlidingMode mode = growingSlidingMode(mu, nu);
      ASSERT_TRUE(mode.growing);
      const Complex root = determinantRoot(mu, nu);
      EXPECT_LT(std::abs(root - mode.eta), 1e-9) << "mu " << mu << " nu " << nu << ": " << root << " vs " << mode.eta;
    }
  }
}

TEST(SlidingDispersion, RefusesPoissonRatioOutsideTheRangeAndAZeroWavenumberSign) {
  EXPECT_THROW(slidingDispersion(Complex(1.4, 0.1), 1.2, 0.5), std::invalid_argument);
  EXPECT_THROW(slidingDispersion(Complex(1.4, 0.1), 1.2, 0.0), std::invalid_argument);
  EXPECT_THROW(countGrowingSlidingRoots(1.2, 1.0 / 3.0, 0), std::invalid_argument);
}

// With the normal-stress memory K = |k| c_s T: i alpha eta^2 (1 - i K eta) = mu (2 - eta^2 - 2 alpha beta)
// for k > 0 (docs/flutter.md, "With a normal-stress memory").
TEST(SlidingDispersionMemory, ZeroMemoryIsTheCoulombRelation) {
  for (double nu : kPoisson)
    for (Complex eta : {Complex(1.4, 0.1), Complex(-2.1, 0.0), Complex(0.3, 0.7), Complex(2.5, 1e-3)}) {
      EXPECT_EQ(slidingDispersion(eta, 1.2, nu, 1, 0.0), slidingDispersion(eta, 1.2, nu));
      EXPECT_EQ(slidingDispersion(eta, 1.2, nu, -1, 0.0), slidingDispersion(eta, 1.2, nu, -1));
    }
  EXPECT_EQ(growingSlidingMode(1.2, 1.0 / 3.0, 0.0).eta, growingSlidingMode(1.2, 1.0 / 3.0).eta);
  EXPECT_EQ(slidingGrowthRate(1.2, 1.0 / 3.0, 55.9, 25e-6, 0.0), slidingGrowthRate(1.2, 1.0 / 3.0, 55.9, 25e-6));
  // The memory term itself: D_K - D_0 = i alpha eta^2 (-i K eta) = K alpha eta^3, and k < 0 is the conjugate.
  const Complex eta(1.3, 0.05);
  const double K = 0.4, nu = 1.0 / 3.0, r = shearToPressureSpeedRatio(nu);
  const Complex alpha = std::sqrt(1.0 - r * r * eta * eta);
  EXPECT_LT(std::abs(slidingDispersion(eta, 1.2, nu, 1, K) - slidingDispersion(eta, 1.2, nu) - K * alpha * eta * eta * eta),
            1e-14);
  EXPECT_LT(std::abs(slidingDispersion(eta, 1.2, nu, -1, K) - std::conj(slidingDispersion(std::conj(eta), 1.2, nu, 1, K))),
            1e-14);
  EXPECT_THROW(slidingDispersion(eta, 1.2, nu, 1, -0.1), std::invalid_argument);
}

// K_c at nu = 1/3 (the note: 0.6 at mu 1.2, 1.1 at mu 1.4), and the root there is on the real axis
// at eta_c^2 = 2 mu (mu - sqrt(mu^2 - 1)).
TEST(SlidingDispersionMemory, CutoffAtNuOneThird) {
  const double nu = 1.0 / 3.0;
  EXPECT_NEAR(memoryCutoff(1.1, nu), 0.4795, 5e-5);
  EXPECT_NEAR(memoryCutoff(1.2, nu), 0.7098, 5e-5);
  EXPECT_NEAR(memoryCutoff(1.4, nu), 1.0751, 5e-5);
  EXPECT_NEAR(memoryCutoff(2.0, nu), 1.9554, 5e-5);
  EXPECT_NEAR(memoryCutoff(1.2, nu), 0.6, 0.15);  // the note, loosely
  EXPECT_NEAR(memoryCutoff(1.4, nu), 1.1, 0.05);
  EXPECT_EQ(memoryCutoff(1.0, nu), 0.0);
  EXPECT_EQ(memoryCutoff(0.9, nu), 0.0);
  for (double mu : {1.1, 1.2, 1.4, 2.0}) {
    const double etaC = std::sqrt(2 * mu * (mu - std::sqrt(mu * mu - 1)));
    EXPECT_LT(std::abs(slidingDispersion(etaC, mu, nu, 1, memoryCutoff(mu, nu))), 1e-13) << "mu " << mu;
  }
}

// The flutter branch (direction +1) grows just below K_c and at no K above it; the count drops by
// exactly one there and nowhere else (a scan: the memory's mode against the sliding stays).
TEST(SlidingDispersionMemory, FlutterBranchGrowsBelowTheCutoffAndNeverAbove) {
  const double nu = 1.0 / 3.0;
  const auto withTheSliding = [nu](double mu, double K) {
    int n = 0;
    for (const SlidingMode& m : growingSlidingModes(mu, nu, K)) n += m.direction > 0;
    return n;
  };
  for (double mu : {1.1, 1.2, 1.4, 2.0}) {
    const double Kc = memoryCutoff(mu, nu);
    EXPECT_EQ(withTheSliding(mu, 0.99 * Kc), 1) << "mu " << mu;
    EXPECT_EQ(withTheSliding(mu, 1.01 * Kc), 0) << "mu " << mu;
    for (double f : {0.05, 0.3, 0.6, 0.9, 0.99}) EXPECT_EQ(countGrowingSlidingRoots(mu, nu, 1, 0, f * Kc), 2);
    for (double f : {1.01, 1.2, 2.0, 5.0, 20.0, 60.0}) {
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, 1, 0, f * Kc), 1) << "mu " << mu << " K/Kc " << f;
      EXPECT_EQ(countGrowingSlidingRoots(mu, nu, -1, 0, f * Kc), 1) << "mu " << mu << " K/Kc " << f;
    }
  }
}

TEST(SlidingDispersionMemory, CutoffWavelengthScalesWithShearSpeedTimesRelaxationTime) {
  const double cs = plateShearSpeed(), nu = 1.0 / 3.0;
  const double reference = memoryCutoffWavelength(1.2, nu, cs, 1e-6);
  EXPECT_NEAR(reference, 2 * M_PI * cs * 1e-6 / memoryCutoff(1.2, nu), 1e-15);
  EXPECT_NEAR(reference, 494.8e-6, 0.1e-6);  // 8.85 c_s T
  EXPECT_NEAR(memoryCutoffWavelength(1.2, nu, cs, 4e-6), 4 * reference, 1e-12);
  EXPECT_NEAR(memoryCutoffWavelength(1.2, nu, 2 * cs, 1e-6), 2 * reference, 1e-12);
  EXPECT_EQ(memoryCutoffWavelength(1.0, nu, cs, 1e-6), 0.0);
  // Just above lambda_c the flutter branch grows, just below it does not (here the memory's mode
  // against the sliding is the only growing root).
  const auto flutterRate = [&](double wavelength) {
    const double K = 2 * M_PI / wavelength * cs * 1e-6;
    for (const SlidingMode& m : growingSlidingModes(1.2, nu, K))
      if (m.direction > 0) return 2 * M_PI / wavelength * cs * m.eta.imag();
    return 0.0;
  };
  EXPECT_GT(flutterRate(1.01 * reference), 0.0);
  EXPECT_EQ(flutterRate(0.99 * reference), 0.0);
}

// The other growing root: against the sliding near -c_p/c_s, for every K > 0 and every mu > 0
// (mu <= 1 included). Its growth rate times T peaks at a finite K and falls to 0 both ways: the
// growth rate is bounded by memoryModeGrowth / T at every wavelength (well-posed, not stable).
TEST(SlidingDispersionMemory, TheMemorysModeAgainstTheSlidingHasBoundedGrowth) {
  const double nu = 1.0 / 3.0;
  EXPECT_NEAR(memoryModeGrowth(1.2, nu), 0.0430, 5e-4);
  EXPECT_NEAR(memoryModeGrowth(1.4, nu), 0.0537, 5e-4);
  EXPECT_NEAR(memoryFlutterGrowth(1.2, nu), 0.0156, 5e-4);
  EXPECT_EQ(memoryFlutterGrowth(0.9, nu), 0.0);
  for (double mu : {0.5, 0.9, 1.2, 1.4, 2.0}) {
    const double bound = memoryModeGrowth(mu, nu);
    EXPECT_GT(bound, 0.0) << "mu " << mu;
    EXPECT_LT(bound, 0.1) << "mu " << mu;
    double previous = INFINITY;
    for (double K : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 100.0}) {
      const std::vector<SlidingMode> modes = growingSlidingModes(mu, nu, K);
      int against = 0;
      for (const SlidingMode& m : modes) {
        if (m.direction > 0) continue;
        ++against;
        EXPECT_LT(std::abs(m.eta + 1.0 / shearToPressureSpeedRatio(nu)), 0.2) << "mu " << mu << " K " << K;
        EXPECT_LE(K * m.eta.imag(), bound * (1 + 1e-9)) << "mu " << mu << " K " << K;
        if (K >= 5.0) {  // past the peak: K Im(eta) falls (about as 1/K^2)
          EXPECT_LT(K * m.eta.imag(), previous);
          previous = K * m.eta.imag();
        }
      }
      EXPECT_EQ(against, 1) << "mu " << mu << " K " << K;
    }
    EXPECT_LT(previous, 0.01 * bound) << "mu " << mu;  // at K = 100
  }
}
