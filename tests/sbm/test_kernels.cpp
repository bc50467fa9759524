// The fast kernel and the plain reference compute the same physics.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

Grading graded(GradedProperty property, double delta) { return sbm::testing::triangular(property, delta); }
Grading both(double delta) { return graded(GradedProperty::Both, delta); }

const char* name(Integrator integrator) { return integrator == Integrator::RK4 ? "rk4" : "verlet"; }

}  // namespace

TEST(Kernels, SameHistoriesForEveryCodePathIntegratorAndLaw) {
  // Every compiled variant: uniform / graded stiffness x uniform / per-column / per-block
  // friction, for RK4 and velocity Verlet, with the Coulomb and the exponential law.
  struct Case {
    Grading grading;
    double sigma;
    double theta;
  };
  const Case cases[] = {{{}, 0.0, 0.0},
                        {graded(GradedProperty::Friction, 0.3), 0.0, 0.0},
                        {{}, 0.05, 45.0},
                        {graded(GradedProperty::YoungsModulus, 0.4), 0.0, 90.0},
                        {both(0.3), 0.0, 30.0},
                        {both(-0.4), 0.05, 60.0}};
  for (const char* law : {"coulomb", "exponential"}) {
    for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
      for (const auto& c : cases) {
        Parameters p = sbm::testing::paperParameters(10, c.sigma, c.grading);
        p.integrator = integrator;
        p.timeStep = defaultTimeStep(p, c.grading);
        p.plate.slidingAngle = c.theta;
        p.frictionLaw.name = law;
        const auto stiffness = buildStiffness(p, c.grading);
        const auto friction = buildFriction(p, c.grading, {3, 1, 2});
        ASSERT_EQ(stiffness.graded, c.grading.gradesModulus());
        ASSERT_EQ(friction.layout, c.sigma > 0 ? SiteLayout::PerSite
                                               : c.grading.gradesFriction() ? SiteLayout::PerColumn
                                                                            : SiteLayout::Uniform);
        const std::string where = std::string(law) + " " + name(integrator) + " theta " + std::to_string(c.theta) +
                                  " sigma " + std::to_string(c.sigma);
        Request q = sbm::testing::defaultRequest(p);
        const Result fast = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Fast);
        const Result plain = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Reference);
        ASSERT_TRUE(fast.friction.peakConfirmed) << where;
        ASSERT_EQ(fast.friction.mu.size(), plain.friction.mu.size()) << where;
        for (std::size_t i = 0; i < fast.friction.mu.size(); ++i)
          ASSERT_NEAR(fast.friction.mu[i], plain.friction.mu[i], 1e-9 * (1 + plain.friction.mu[i])) << where << " step " << i;
        EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, 1e-10) << where;
        EXPECT_NEAR(fast.friction.muKinetic, plain.friction.muKinetic, 1e-9) << where;
        ASSERT_EQ(fast.firstSlipTime.size(), plain.firstSlipTime.size());
        for (std::size_t i = 0; i < fast.firstSlipTime.size(); ++i)
          EXPECT_EQ(fast.firstSlipTime[i], plain.firstSlipTime[i]) << where << " block " << i;
      }
    }
  }
}

TEST(Kernels, TheExponentialLawOnAPlate) {
  // Same plate, same draws. The loading is elastic: until the first block slips the laws cannot
  // differ. With v_c far above every slip speed the sliding friction stays at mu_s: the plate
  // keeps sliding at its static peak, far above Coulomb's mu_k.
  const Grading g = both(0.2);
  Parameters p = sbm::testing::paperParameters(12, 0.028, g);
  const Request q = sbm::testing::defaultRequest(p);
  const Result coulomb = simulate(p, g, q, {5, 0, 0});
  p.frictionLaw.name = "exponential";
  p.frictionLaw.criticalVelocity = 1e3;
  const Result exponential = simulate(p, g, q, {5, 0, 0});
  // No weakening, no avalanche: the peak is not lower, and sliding stays within 1 % of it.
  EXPECT_GE(exponential.friction.muStatic, coulomb.friction.muStatic);
  EXPECT_GT(exponential.friction.muKinetic, 0.99 * exponential.friction.muStatic);
  EXPECT_LT(coulomb.friction.muKinetic, 0.9 * coulomb.friction.muStatic);
  // Before any block slips the laws cannot differ: the loading is elastic.
  const std::size_t loading = std::size_t(0.5 * p.loadingTime() / p.timeStep);
  for (std::size_t i = 0; i < loading; ++i) ASSERT_EQ(exponential.friction.mu[i], coulomb.friction.mu[i]) << i;
}

TEST(Kernels, StatesAgreeThroughStickAndSlip) {
  // Graded stiffness and friction, through loading, the peak and sliding: the
  // displacements of both kernels stay equal to round-off, for both integrators and laws (the
  // state law: test_state_kernels.cpp).
  const Grading g = both(0.5);
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    Parameters p = sbm::testing::paperParameters(9, 0.0, g);
    p.integrator = integrator;
    p.timeStep = defaultTimeStep(p, g);
    const int steps = int(1.3 * p.loadingTime() / p.timeStep);
    const auto stiffness = buildStiffness(p, g);
    const auto friction = buildFriction(p, g, {});
    auto compare = [&](auto law) {
      using Law = decltype(law);
      FastLattice<Law> fast(stiffness, law, motionOf(p, p.timeStep, p.damping));
      ReferenceLattice<Law> plain(stiffness, law, motionOf(p, p.timeStep, p.damping));
      for (int step = 0; step < steps; ++step) {
        fast.step();
        plain.step();
      }
      EXPECT_GT(fast.slippedBlocks(), 0);
      EXPECT_EQ(fast.slippedBlocks(), plain.slippedBlocks());
      const auto ux = plain.displacementX();
      const auto vx = plain.velocityX();
      double fastest = p.plate.velocity;
      for (double v : vx) fastest = std::max(fastest, std::fabs(v));
      for (std::size_t i = 0; i < ux.size(); ++i) {
        EXPECT_NEAR(fast.displacementX()[i], ux[i], 1e-9 * p.spacing()) << Law::name << " " << name(integrator) << i;
        EXPECT_NEAR(fast.velocityX()[i], vx[i], 1e-9 * fastest) << Law::name << " " << name(integrator) << i;
      }
    };
    compare(CoulombStickSlip::make(friction, p.frictionLaw));
    compare(ExponentialVelocityWeakening::make(friction, p.frictionLaw));
  }
}

TEST(Kernels, VelocityVerletAgreesWithRK4) {
  // Two schemes, one physics: on a graded, dispersed plate, at steps well inside both stability
  // limits, the global coefficients agree to 0.2 % (docs/accuracy.md has the full study).
  const Grading g = both(0.2);
  for (double safety : {0.02, 0.05}) {
    Parameters rk4 = sbm::testing::paperParameters(24, 0.028, g);
    rk4.integrator = Integrator::RK4;
    rk4.timeStep = safety * stableTimeStep(rk4, g);
    Parameters verlet = rk4;
    verlet.integrator = Integrator::VelocityVerlet;
    verlet.timeStep = safety * stableTimeStep(verlet, g);
    const Request q = sbm::testing::defaultRequest(rk4);
    const Result a = simulate(rk4, g, q, {2, 0, 0});
    const Result b = simulate(verlet, g, q, {2, 0, 0});
    const double tolerance = 0.002;
    EXPECT_NEAR(b.friction.muStatic, a.friction.muStatic, tolerance * a.friction.muStatic) << "safety " << safety;
    EXPECT_NEAR(b.friction.muKinetic, a.friction.muKinetic, tolerance * a.friction.muKinetic) << "safety " << safety;
    EXPECT_NEAR(b.friction.peakTime, a.friction.peakTime, 0.01 * a.friction.peakTime) << "safety " << safety;
  }
}
