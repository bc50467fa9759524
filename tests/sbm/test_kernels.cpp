// The fast kernel and the plain reference compute the same physics.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

Grading both(double delta) {
  Grading g;
  g.profile = GradingProfile::Triangular;
  g.property = GradedProperty::Both;
  g.delta = delta;
  g.bands = 4;
  return g;
}

}  // namespace

TEST(Kernels, SameHistoriesForEveryCodePath) {
  // Uniform and graded stiffness, no dispersion / per-column / per-block friction.
  struct Case {
    Grading grading;
    double sigma;
    double theta;
  };
  const Case cases[] = {{{}, 0.0, 0.0}, {both(0.3), 0.0, 30.0}, {both(-0.4), 0.05, 60.0}, {{}, 0.05, 0.0}};
  for (const auto& c : cases) {
    Parameters p = sbm::testing::paperParameters(10, c.sigma, c.grading);
    p.integrator = Integrator::RK4;  // the plain reference implements RK4
    p.plate.slidingAngle = c.theta;
    Request q = sbm::testing::defaultRequest(p);
    const Result fast = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Fast);
    const Result plain = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Reference);
    ASSERT_EQ(fast.friction.mu.size(), plain.friction.mu.size());
    for (std::size_t i = 0; i < fast.friction.mu.size(); ++i) ASSERT_NEAR(fast.friction.mu[i], plain.friction.mu[i], 1e-9 * (1 + plain.friction.mu[i])) << i;
    EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, 1e-10);
    EXPECT_NEAR(fast.friction.muKinetic, plain.friction.muKinetic, 1e-9);
    ASSERT_EQ(fast.firstSlipTime.size(), plain.firstSlipTime.size());
    for (std::size_t i = 0; i < fast.firstSlipTime.size(); ++i) EXPECT_EQ(fast.firstSlipTime[i], plain.firstSlipTime[i]);
  }
}

TEST(Kernels, StatesAgreeThroughStickAndSlip) {
  // Graded stiffness and friction, 3000 steps through loading, the peak and sliding: the
  // displacements of both kernels stay equal to round-off.
  const Grading g = both(0.5);
  Parameters p = sbm::testing::paperParameters(9, 0.0, g);
  p.integrator = Integrator::RK4;  // the plain reference implements RK4
  const auto stiffness = buildStiffness(p, g);
  const auto friction = buildFriction(p, g, {});
  FastLattice fast(stiffness, friction, motionOf(p, p.timeStep, p.damping));
  ReferenceLattice plain(stiffness, friction, motionOf(p, p.timeStep, p.damping));
  for (int step = 0; step < 3000; ++step) {
    fast.step();
    plain.step();
  }
  const auto ux = plain.displacementX();
  for (std::size_t i = 0; i < ux.size(); ++i) EXPECT_NEAR(fast.displacementX()[i], ux[i], 1e-9 * p.spacing()) << i;
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
