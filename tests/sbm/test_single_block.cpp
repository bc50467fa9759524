// One block on a slider spring (a uniform lattice without dispersion moves as one block: its
// internal springs stay at rest length). Undamped Amontons-Coulomb stick-slip has an exact
// solution: the force peaks at mu_s F_n, drops to (2 mu_k - mu_s) F_n when the block re-sticks,
// and the period is T = 2 (mu_s - mu_k) F_n / (K v) + (2 pi - 2 atan(A omega / v)) / omega with
// A = (mu_s - mu_k) F_n / K and omega = sqrt(K / m).
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

struct StickSlipCycle {
  std::vector<double> peakTimes, peakForces, troughForces;
};

template <class Lattice>
StickSlipCycle runStickSlip(const Parameters& p, double duration) {
  Grading uniform;
  const auto stiffness = buildStiffness(p, uniform);
  const auto friction = buildFriction(p, uniform, {});
  Lattice lattice(stiffness, friction, motionOf(p, p.timeStep, p.damping));
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

template <class Lattice>
void checkAgainstAnalytic(Integrator integrator = Integrator::RK4) {
  Parameters p = sbm::testing::paperParameters(2, 0.0, {}, 0.02, 0.0);  // undamped, small step
  p.integrator = integrator;
  p.damping = 0.0;
  const double fn = p.normalForcePerBlock();
  const double k = p.sliderStiffness(p.plate.youngsModulus);
  const double omega = std::sqrt(k / p.blockMass());
  const double amplitude = (p.plate.muStatic - p.plate.muKinetic) * fn / k;
  const double period = 2.0 * amplitude / p.plate.velocity + (2.0 * M_PI - 2.0 * std::atan(amplitude * omega / p.plate.velocity)) / omega;
  const auto cycle = runStickSlip<Lattice>(p, 3.5 * period);
  ASSERT_GE(cycle.peakTimes.size(), 3u);
  // The force can overshoot the threshold by at most one step of loading, K v dt.
  const double loadingPerStep = k * p.plate.velocity * p.timeStep;
  for (double peak : cycle.peakForces) {
    EXPECT_GE(peak, p.plate.muStatic * fn - 1e-12 * fn);
    EXPECT_LE(peak, p.plate.muStatic * fn + 1.01 * loadingPerStep);
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
