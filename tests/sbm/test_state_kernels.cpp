// The state law on the fast kernel (src/sbm/block_state.hpp) against the plain reference.
//
// The standard is the stateless laws' (test_kernels.cpp): the kernels add the springs in different
// orders, so they agree to round-off, not bit for bit: mu(t) to 1e-9 at every step, mu_s to 1e-10,
// mu_k to 1e-9, the first slips at the same step. The state law's onset, though, amplifies
// round-off by about 1e3 a step: the reference against itself with one block's mu_k one ulp
// higher departs by 1e-3 within a few steps of the first slip (TheReferenceItselfAmplifiesRoundOff).
// No pair of kernels can then meet 1e-9 on a plate whose blocks do not move as one. So:
//  - a uniform plate without dispersion (it moves as one block: slip weakening, healing at rest,
//    re-slips): the stateless standard over the whole history;
//  - graded and dispersed plates: the stateless standard from t = 0 through kOnsetSteps steps past
//    the first slip; after it mu_s and mu_k to kChaoticSpread, the spread the amplified round-off
//    leaves (measured at most 1.0e-3 on these plates); the same under the load-dependent pressure;
//  - the state itself: every block's theta is, bit for bit at every step, the reference kernel's
//    update (StateWeakening::advance, then commit) applied to the fast kernel's own slips, through
//    the quiet-phase jump, the active set and its held tiles.
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

constexpr int kOnsetSteps = 10;          // steps past the first slip still held to 1e-9 (round-off grows 1e3 a step)
constexpr double kChaoticSpread = 2e-3;  // |delta mu_s|, |delta mu_k| after the onset (measured <= 1.0e-3)

Grading graded(GradedProperty property, double delta) { return sbm::testing::triangular(property, delta); }

const char* name(Integrator integrator) { return integrator == Integrator::RK4 ? "rk4" : "verlet"; }

Parameters stateLawPlate(int blocksPerSide, double sigma, const Grading& g, Integrator integrator, double slipLength) {
  Parameters p = sbm::testing::paperParameters(blocksPerSide, sigma, g);
  p.integrator = integrator;
  p.timeStep = defaultTimeStep(p, g);
  p.frictionLaw.name = "state";
  p.frictionLaw.slipLength = slipLength;
  return p;
}

// mu(t) of both runs to the stateless standard at every sample up to time `until` [s].
void expectSameHistory(const Result& fast, const Result& plain, double until, const std::string& where) {
  ASSERT_FALSE(plain.friction.mu.empty()) << where;
  const std::size_t n = std::min(fast.friction.mu.size(), plain.friction.mu.size());
  for (std::size_t i = 0; i < n && plain.friction.time[i] <= until; ++i)
    ASSERT_NEAR(fast.friction.mu[i], plain.friction.mu[i], 1e-9 * (1 + plain.friction.mu[i])) << where << " step " << i;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(StateKernels, TheUniformPlateGivesTheReferenceHistoryThroughout) {
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    for (double slipLength : {2.5e-8, 1e-7}) {  // kappa_SBM 0.41 and 1.64
      const Parameters p = stateLawPlate(10, 0.0, {}, integrator, slipLength);
      const std::string where = std::string(name(integrator)) + " D_c " + std::to_string(slipLength);
      const Request q = sbm::testing::defaultRequest(p);
      const Result fast = simulate(p, {}, q, {3, 1, 2}, Kernel::Fast);
      const Result plain = simulate(p, {}, q, {3, 1, 2}, Kernel::Reference);
      ASSERT_TRUE(fast.friction.peakConfirmed) << where;
      ASSERT_EQ(fast.friction.mu.size(), plain.friction.mu.size()) << where;
      expectSameHistory(fast, plain, plain.endTime, where);
      EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, 1e-10) << where;
      EXPECT_NEAR(fast.friction.muKinetic, plain.friction.muKinetic, 1e-9) << where;
      EXPECT_EQ(fast.firstSlipTime, plain.firstSlipTime) << where;
    }
  }
}

TEST(StateKernels, GradedAndDispersedPlatesGiveTheReferenceHistoryThroughTheOnset) {
  struct Case {
    const char* what;
    Grading grading;
    double sigma, theta, slipLength;
  };
  const Case cases[] = {{"graded friction", graded(GradedProperty::Friction, 0.3), 0.0, 0.0, 2.5e-8},
                        {"graded E, dispersed", graded(GradedProperty::YoungsModulus, 0.4), 0.05, 30.0, 2.5e-8},
                        {"both graded, dispersed", graded(GradedProperty::Both, -0.4), 0.05, 0.0, 1e-7}};
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    for (const auto& c : cases) {
      Parameters p = stateLawPlate(10, c.sigma, c.grading, integrator, c.slipLength);
      p.plate.slidingAngle = c.theta;
      const std::string where = std::string(c.what) + " " + name(integrator);
      const Request q = sbm::testing::defaultRequest(p);
      const Result fast = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Fast);
      const Result plain = simulate(p, c.grading, q, {3, 1, 2}, Kernel::Reference);
      ASSERT_TRUE(fast.friction.peakConfirmed) << where;
      EXPECT_EQ(fast.friction.firstSlipTime, plain.friction.firstSlipTime) << where;
      expectSameHistory(fast, plain, plain.friction.firstSlipTime + kOnsetSteps * p.timeStep, where);
      EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, kChaoticSpread) << where;
      EXPECT_NEAR(fast.friction.muKinetic, plain.friction.muKinetic, kChaoticSpread) << where;
    }
  }
}

TEST(StateKernels, TheReferenceItselfAmplifiesRoundOff) {
  // Why the standard above stops at the onset: the reference kernel against itself with one
  // block's mu_k one ulp higher. Equal through the loading; within 2 loading times apart by far
  // more than the 1e-9 the kernels are held to.
  const Grading g = graded(GradedProperty::Friction, 0.3);
  const Parameters p = stateLawPlate(10, 0.0, g, Integrator::VelocityVerlet, 1e-7);
  const auto stiffness = buildStiffness(p, g);
  const FrictionField friction = buildFriction(p, g, {3, 1, 2});
  FrictionField nudged = friction;
  nudged.kineticStrength[0] = std::nextafter(nudged.kineticStrength[0], 1.0);
  const std::size_t blocks = std::size_t(p.blocksPerSide) * p.blocksPerSide;
  const Motion motion = motionOf(p, p.timeStep, p.damping);
  ReferenceLattice<StateWeakening> a(stiffness, StateWeakening::make(friction, p.frictionLaw, blocks), motion);
  ReferenceLattice<StateWeakening> b(stiffness, StateWeakening::make(nudged, p.frictionLaw, blocks), motion);
  double largest = 0;
  while (a.time() < 2 * p.loadingTime()) {
    const double fa = a.step().sliderForceX, fb = b.step().sliderForceX;
    if (a.slippedBlocks() == 0) {
      ASSERT_EQ(fa, fb) << "loading, step " << a.steps();
    }
    largest = std::max(largest, std::fabs(fa - fb) / std::fabs(fa));
  }
  std::printf("reference against itself, one mu_k one ulp higher: mu(t) apart by up to %.2g\n", largest);
  EXPECT_GT(largest, 1e-6);
}

TEST(StateKernels, EveryStateIsTheReferenceUpdateOfTheBlocksOwnSlipBitForBit) {
  // A 30 x 30 E-graded, dispersed plate sliding at 60 degrees through 1.5 loading times, idle work
  // skipped: the quiet-phase jump, and with Verlet the active set and its held tiles, which here
  // hold blocks that slid and heal while held (5633 such block-steps, measured).
  Grading g = graded(GradedProperty::YoungsModulus, -0.4);
  g.profile = GradingProfile::Linear;
  for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    Parameters p = stateLawPlate(30, 0.028, g, integrator, 2.5e-8);
    p.plate.slidingAngle = 60.0;
    const std::size_t blocks = std::size_t(p.blocksPerSide) * p.blocksPerSide;
    const StateWeakening law = StateWeakening::make(buildFriction(p, g, {4, 4, 4}), p.frictionLaw, blocks);
    FastLattice<StateWeakening> fast(buildStiffness(p, g), law, motionOf(p, p.timeStep, p.damping));
    StateWeakening shadow = law;  // the reference kernel's calls, on the fast kernel's slips
    std::vector<double> previousX(blocks, 0.0), previousY(blocks, 0.0);
    const std::int64_t steps = std::int64_t(1.5 * p.loadingTime() / p.timeStep);
    std::int64_t healed = 0;  // block-steps at rest with theta > 0
    for (std::int64_t n = 0; n < steps; ++n) {
      for (std::size_t i = 0; i < blocks; ++i) {  // the slip of the step that ended at t_n
        const double x = fast.displacementX()[i], y = fast.displacementY()[i];
        shadow.advance(int(i), slipOf(x - previousX[i], y - previousY[i]), p.timeStep);
        healed += x == previousX[i] && y == previousY[i] && shadow.state[i] > 0;
        previousX[i] = x;
        previousY[i] = y;
      }
      shadow.commit();
      fast.step();
      for (std::size_t i = 0; i < blocks; ++i)
        ASSERT_TRUE(sameBits(fast.law().state[i], shadow.state[i])) << name(integrator) << " step " << n << " block " << i;
    }
    EXPECT_GT(fast.quietSteps(), 0) << name(integrator);
    EXPECT_GT(healed, 0) << name(integrator);
    if (integrator == Integrator::VelocityVerlet) {
      EXPECT_GT(fast.heldTileSteps(), 0);
    }
  }
}

TEST(StateKernels, UnderTheLoadDependentPressure) {
  // The moment-balance pressure rescales the strengths every step (no quiet-phase jump, no held
  // tiles): both kernels keep its balances, and agree as above.
  const Grading g = graded(GradedProperty::Friction, 0.3);
  const Parameters p = stateLawPlate(12, 0.028, g, Integrator::VelocityVerlet, 2.5e-8);
  const auto [fast, plain] = sbm::testing::bothKernelsUnderMomentBalance(p, g);
  EXPECT_EQ(fast.friction.firstSlipTime, plain.friction.firstSlipTime);
  expectSameHistory(fast, plain, plain.friction.firstSlipTime + kOnsetSteps * p.timeStep, "pressure");
  EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, kChaoticSpread);
  EXPECT_NEAR(fast.friction.muKinetic, plain.friction.muKinetic, kChaoticSpread);
}
