// One block on a slider spring (a uniform lattice without dispersion moves as one block: its
// internal springs stay at rest length). Undamped Amontons-Coulomb stick-slip has an exact
// solution: the force peaks at mu_s F_n, drops to (2 mu_k - mu_s) F_n when the block re-sticks,
// and the period is T = 2 (mu_s - mu_k) F_n / (K v) + (2 pi - 2 atan(A omega / v)) / omega with
// A = (mu_s - mu_k) F_n / K and omega = sqrt(K / m).
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

struct StickSlipCycle {
  std::vector<double> peakTimes, peakForces, troughForces;
};

template <template <class> class Lattice, class Law = CoulombStickSlip>
StickSlipCycle runStickSlip(const Parameters& p, double duration) {
  Grading uniform;
  const auto stiffness = buildStiffness(p, uniform);
  const auto friction = buildFriction(p, uniform, {});
  Lattice<Law> lattice(stiffness, Law::make(friction, p.frictionLaw), motionOf(p, p.timeStep, p.damping));
  const double blocks = double(p.blocksPerSide) * p.blocksPerSide;
  StickSlipCycle cycle;
  double previous = 0, beforePrevious = 0;
  double trough = 1e300;
  while (lattice.time() < duration) {
    const auto o = lattice.step();
    const double force = o.sliderForceX / blocks;  // per block
    if (previous > beforePrevious && previous > force) {  // a local maximum: a slip starts
      cycle.peakTimes.push_back(o.time - p.timeStep);
      cycle.peakForces.push_back(previous);
      if (cycle.peakTimes.size() > 1) cycle.troughForces.push_back(trough);
      trough = 1e300;
    }
    trough = std::min(trough, force);
    beforePrevious = previous;
    previous = force;
  }
  return cycle;
}

// criticalVelocity > 0: the exponential law with that v_c instead of Coulomb.
template <template <class> class Lattice>
void checkAgainstAnalytic(Integrator integrator = Integrator::RK4, double criticalVelocity = 0.0) {
  Parameters p = sbm::testing::paperParameters(2, 0.0, {}, 0.02, 0.0);  // undamped, small step
  p.integrator = integrator;
  p.frictionLaw.name = criticalVelocity > 0 ? "exponential" : "coulomb";
  p.frictionLaw.criticalVelocity = criticalVelocity > 0 ? criticalVelocity : 1e-4;
  p.damping = 0.0;
  const double fn = p.normalForcePerBlock();
  const double k = p.sliderStiffness(p.plate.youngsModulus);
  const double omega = std::sqrt(k / p.blockMass());
  const double amplitude = (p.plate.muStatic - p.plate.muKinetic) * fn / k;
  const double period = 2.0 * amplitude / p.plate.velocity + (2.0 * M_PI - 2.0 * std::atan(amplitude * omega / p.plate.velocity)) / omega;
  const auto cycle = criticalVelocity > 0 ? runStickSlip<Lattice, ExponentialVelocityWeakening>(p, 3.5 * period)
                                           : runStickSlip<Lattice>(p, 3.5 * period);
  ASSERT_GE(cycle.peakTimes.size(), 3u);
  // The force can overshoot the threshold by at most one step of loading, K v dt.
  const double loadingPerStep = k * p.plate.velocity * p.timeStep;
  // The exponential law at v_c -> 0: a block starting from rest feels mu(0) = mu_s for its
  // first step (the friction is frozen from the start-of-step speed): one more step of loading.
  const double stepsOfLoading = criticalVelocity > 0 ? 2.01 : 1.01;
  for (double peak : cycle.peakForces) {
    EXPECT_GE(peak, p.plate.muStatic * fn - 1e-12 * fn);
    EXPECT_LE(peak, p.plate.muStatic * fn + stepsOfLoading * loadingPerStep);
  }
  for (double trough : cycle.troughForces) EXPECT_NEAR(trough / fn, 2 * p.plate.muKinetic - p.plate.muStatic, 0.01);
  for (std::size_t i = 1; i < cycle.peakTimes.size(); ++i)
    EXPECT_NEAR(cycle.peakTimes[i] - cycle.peakTimes[i - 1], period, 0.005 * period) << "cycle " << i;
  // The first peak comes after loading from rest: t = mu_s F_n / (K v).
  EXPECT_NEAR(cycle.peakTimes[0], p.plate.muStatic * fn / (k * p.plate.velocity), 2 * p.timeStep);
}

}  // namespace

TEST(SingleBlock, StickSlipMatchesAnalyticSolutionFastKernel) { checkAgainstAnalytic<FastLattice>(); }
TEST(SingleBlock, StickSlipMatchesAnalyticSolutionReferenceKernel) { checkAgainstAnalytic<ReferenceLattice>(); }
TEST(SingleBlock, StickSlipMatchesAnalyticSolutionVelocityVerlet) {
  checkAgainstAnalytic<FastLattice>(Integrator::VelocityVerlet);
}

// The exponential law, mu(v) = mu_k + (mu_s - mu_k) exp(-v/v_c). As v_c -> 0 it is Coulomb's law
// at every speed but zero (a block starting from rest feels mu_s for its first step): the exact
// Coulomb solution above holds, peaks at mu_s F_n included.
TEST(SingleBlock, ExponentialLawTendsToCoulombAsTheCriticalVelocityVanishes) {
  checkAgainstAnalytic<FastLattice>(Integrator::RK4, 1e-12);
  checkAgainstAnalytic<ReferenceLattice>(Integrator::RK4, 1e-12);
  checkAgainstAnalytic<FastLattice>(Integrator::VelocityVerlet, 1e-12);
  checkAgainstAnalytic<ReferenceLattice>(Integrator::VelocityVerlet, 1e-12);
}

namespace {

// Independent reference for one slip of an undamped block under the exponential law: from rest
// at the static threshold (t = 0, slider force mu_s F_n), m x'' = K (v t - x) - F_n mu(x'),
// integrated with a fine classical RK4 and continuous friction until the block stops.
struct Slip {
  double highest, lowest;  // slider force [N]
  double duration;         // [s]
};
Slip exponentialSlip(double mass, double k, double v, double fn, double muS, double muK,
                                          double vC) {
  const double x0 = -muS * fn / k;  // slider ahead of the block by the static threshold
  auto acceleration = [&](double t, double x, double u) {
    return (k * (v * t - x) - fn * (muK + (muS - muK) * std::exp(-u / vC))) / mass;
  };
  const double h = 1e-5 * std::sqrt(mass / k);
  double t = 0, x = x0, u = 0, lowest = muS * fn, highest = muS * fn;
  for (;;) {
    const double a1 = acceleration(t, x, u);
    const double a2 = acceleration(t + h / 2, x + h / 2 * u, u + h / 2 * a1);
    const double a3 = acceleration(t + h / 2, x + h / 2 * (u + h / 2 * a1), u + h / 2 * a2);
    const double a4 = acceleration(t + h, x + h * (u + h / 2 * a2), u + h * a3);
    x += h / 6 * (u + 2 * (u + h / 2 * a1) + 2 * (u + h / 2 * a2) + (u + h * a3));
    u += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    t += h;
    lowest = std::min(lowest, k * (v * t - x));
    highest = std::max(highest, k * (v * t - x));
    if (u < 0 || t > 100 * std::sqrt(mass / k)) return {highest, lowest, t};
  }
}

}  // namespace

TEST(SingleBlock, ExponentialLawSlipMatchesAnIndependentIntegration) {
  // A v_c of the order of the slip speed, where the law's weakening matters: the trough of the
  // kernels' force (friction frozen per step) agrees with a fine continuous integration, and lies
  // between Coulomb's 2 mu_k - mu_s and mu_s.
  Parameters p = sbm::testing::paperParameters(2, 0.0, {}, 0.02, 0.0);
  p.damping = 0.0;
  const double fn = p.normalForcePerBlock();
  const double k = p.sliderStiffness(p.plate.youngsModulus);
  const double omega = std::sqrt(k / p.blockMass());
  const double slipSpeed = (p.plate.muStatic - p.plate.muKinetic) * fn / k * omega;  // Coulomb's peak speed
  p.frictionLaw.name = "exponential";
  p.frictionLaw.criticalVelocity = 0.3 * slipSpeed;
  const Slip slip = exponentialSlip(p.blockMass(), k, p.plate.velocity, fn, p.plate.muStatic, p.plate.muKinetic,
                                    p.frictionLaw.criticalVelocity);
  const double trough = slip.lowest;
  EXPECT_GT(trough / fn, 2 * p.plate.muKinetic - p.plate.muStatic + 0.02);
  EXPECT_LT(trough / fn, p.plate.muStatic - 0.02);
  EXPECT_GT(slip.duration, 0.5 / omega);
  const double loading = 2.5 * p.plate.muStatic * fn / (k * p.plate.velocity);
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    p.integrator = integrator;
    const auto fast = runStickSlip<FastLattice, ExponentialVelocityWeakening>(p, loading);
    const auto plain = runStickSlip<ReferenceLattice, ExponentialVelocityWeakening>(p, loading);
    ASSERT_GE(fast.troughForces.size(), 1u);
    ASSERT_EQ(fast.troughForces.size(), plain.troughForces.size());
    EXPECT_NEAR(fast.troughForces[0] / fn, trough / fn, 0.005);
    EXPECT_NEAR(plain.troughForces[0] / fn, trough / fn, 0.005);
    // The force overshoots mu_s F_n while the slow block weakens its friction: as continuous.
    EXPECT_GT(fast.peakForces[0], p.plate.muStatic * fn);
    EXPECT_NEAR(fast.peakForces[0] / fn, slip.highest / fn, 0.001);
    EXPECT_NEAR(plain.peakForces[0] / fn, slip.highest / fn, 0.001);
  }
}

TEST(SingleBlock, ExponentialLawWithALargeCriticalVelocitySlidesAtTheStaticThreshold) {
  // v_c far above every speed: mu(v) = mu_s while sliding. Once the force reaches mu_s F_n the
  // block, released from rest with a slider running at v, catches up as an undamped oscillator
  // about the threshold: the force swings by K v / omega on either side (the velocity between 0
  // and 2 v), where Coulomb's law drops it by 2 (mu_s - mu_k) F_n.
  Parameters p = sbm::testing::paperParameters(2, 0.0, {}, 0.02, 0.0);
  p.damping = 0.0;
  p.frictionLaw.name = "exponential";
  p.frictionLaw.criticalVelocity = 1e6;
  const double fn = p.normalForcePerBlock();
  const double k = p.sliderStiffness(p.plate.youngsModulus);
  const double onset = p.plate.muStatic * fn / (k * p.plate.velocity);
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    p.integrator = integrator;
    Grading uniform;
    const auto friction = buildFriction(p, uniform, {});
    FastLattice<ExponentialVelocityWeakening> lattice(buildStiffness(p, uniform),
                                                      ExponentialVelocityWeakening::make(friction, p.frictionLaw),
                                                      motionOf(p, p.timeStep, p.damping));
    const double blocks = double(p.blocksPerSide) * p.blocksPerSide;
    const double swing = k * p.plate.velocity / std::sqrt(k / p.blockMass());
    const double band = 1.02 * swing + 2.0 * k * p.plate.velocity * p.timeStep;
    double lowest = 1e300, highest = 0.0;
    while (lattice.time() < 3.0 * onset) {
      const auto o = lattice.step();
      if (o.time > 1.1 * onset) {
        lowest = std::min(lowest, o.sliderForceX / blocks);
        highest = std::max(highest, o.sliderForceX / blocks);
      }
    }
    EXPECT_GT(lattice.slippedBlocks(), 0);
    EXPECT_GE(lowest, p.plate.muStatic * fn - band) << (integrator == Integrator::RK4 ? "rk4" : "verlet");
    EXPECT_LE(highest, p.plate.muStatic * fn + band) << (integrator == Integrator::RK4 ? "rk4" : "verlet");
    EXPECT_NEAR(0.5 * (highest - lowest), swing, 0.02 * swing);
    EXPECT_LT(2.0 * swing, 0.1 * (p.plate.muStatic - p.plate.muKinetic) * fn);  // far from a Coulomb drop
  }
}

TEST(SingleBlock, DampingShortensTheOvershoot) {
  // With damping the block stops earlier: the trough rises above the undamped 2 mu_k - mu_s.
  // Damping ratio 0.3 of the slider mode (omega_s = sqrt(K_s/m) does not depend on N_b).
  Parameters p = sbm::testing::paperParameters(2, 0.0, {}, 0.02, 0.0);
  const double k = p.sliderStiffness(p.plate.youngsModulus);
  p.damping = 2 * 0.3 * std::sqrt(k / p.blockMass());
  const auto cycle = runStickSlip<FastLattice>(p, 3.0 * p.plate.muStatic * p.normalForcePerBlock() / (k * p.plate.velocity));
  ASSERT_GE(cycle.troughForces.size(), 1u);
  EXPECT_GT(cycle.troughForces[0] / p.normalForcePerBlock(), 2 * p.plate.muKinetic - p.plate.muStatic + 0.05);
  EXPECT_LT(cycle.troughForces[0] / p.normalForcePerBlock(), p.plate.muKinetic);
}
