// Skipping idle work (-sbm_skip_idle, quiet_phase.hpp) changes no result: the jump over the phase
// before the first slip is bit for bit the stepped run, on every code path of the kernel.
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/quiet_phase.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

Grading graded(GradingProfile profile, GradedProperty property, double delta) {
  return sbm::testing::grading(profile, property, delta, 4);
}

// Equal as bits (NaN equals NaN; +0 and -0 differ).
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameBits(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(sameBits(a[i], b[i])) << what << " [" << i << "] " << a[i] << " vs " << b[i];
}

void expectSameResults(const Result& skipped, const Result& stepped, const std::string& where) {
  expectSameBits(skipped.friction.time, stepped.friction.time, where + " history time");
  expectSameBits(skipped.friction.mu, stepped.friction.mu, where + " history mu");
  expectSameBits(skipped.friction.forceX, stepped.friction.forceX, where + " history F_x");
  expectSameBits(skipped.friction.forceY, stepped.friction.forceY, where + " history F_y");
  const std::vector<double> a = {skipped.friction.muStatic, skipped.friction.peakTime, skipped.friction.muKinetic,
                                 skipped.friction.firstSlipTime, skipped.endTime, skipped.energy, skipped.sliderWork};
  const std::vector<double> b = {stepped.friction.muStatic, stepped.friction.peakTime, stepped.friction.muKinetic,
                                 stepped.friction.firstSlipTime, stepped.endTime, stepped.energy, stepped.sliderWork};
  expectSameBits(a, b, where + " mu_s, peak time, mu_k, first slip, end, energy, work");
  EXPECT_EQ(skipped.friction.peakConfirmed, stepped.friction.peakConfirmed) << where;
  EXPECT_EQ(skipped.steps, stepped.steps) << where;
  expectSameBits(skipped.firstSlipTime, stepped.firstSlipTime, where + " first-slip map");
  ASSERT_EQ(skipped.snapshots.size(), stepped.snapshots.size()) << where;
  for (std::size_t k = 0; k < skipped.snapshots.size(); ++k)
    expectSameBits(skipped.snapshots[k].sigmaXOverP, stepped.snapshots[k].sigmaXOverP, where + " snapshot");
}

// The uniform plate's friction sites, one per block, with block `weak` at 90 % of the others'
// static strength.
FrictionSites withOneWeakBlock(const Parameters& p, int weak) {
  FrictionSites sites = buildFriction(p, {}, {});
  const int blocks = p.blocksPerSide * p.blocksPerSide;
  const double strong = sites.staticStrength[0], kinetic = sites.kineticStrength[0];
  sites.layout = SiteLayout::PerSite;
  sites.columns = p.blocksPerSide;
  sites.staticStrength.assign(blocks, strong);
  sites.kineticStrength.assign(blocks, kinetic);
  sites.staticStrength[weak] = 0.9 * strong;
  return sites;
}

const char* name(Integrator integrator) { return integrator == Integrator::RK4 ? "rk4" : "verlet"; }

}  // namespace

TEST(SkipIdle, BitForBitTheSteppedRunOnEveryCodePath) {
  // Uniform and graded E x uniform, per-column and per-block friction x both integrators x both
  // laws (and the state law), with and without snapshots and first-slip
  // maps, at several angles.
  struct Case {
    Grading grading;
    double sigma, theta;
    bool snapshots, kinetic;
  };
  const Grading friction = graded(GradingProfile::Linear, GradedProperty::Friction, 0.3);
  const Grading modulus = graded(GradingProfile::Triangular, GradedProperty::YoungsModulus, 0.4);
  const Grading both = graded(GradingProfile::Linear, GradedProperty::Both, -0.3);
  const Case cases[] = {{{}, 0.0, 0.0, false, true},       {friction, 0.0, 30.0, true, true},
                        {{}, 0.05, 45.0, true, false},     {modulus, 0.0, 90.0, false, true},
                        {modulus, 0.028, 0.0, true, true}, {both, 0.05, 135.0, false, false}};
  for (const char* law : {"coulomb", "exponential", "state"}) {
    for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
      for (const auto& c : cases) {
        Parameters p = sbm::testing::paperParameters(12, c.sigma, c.grading);
        p.integrator = integrator;
        p.timeStep = defaultTimeStep(p, c.grading);
        p.plate.slidingAngle = c.theta;
        p.frictionLaw.name = law;
        Request q = sbm::testing::defaultRequest(p);
        q.measurement.kinetic = c.kinetic;
        q.measurement.firstSlipMap = c.snapshots;
        q.measurement.historyInterval = c.kinetic ? 0.0 : 0.01 * p.loadingTime();
        if (c.snapshots) q.snapshotTimes = {0.0, 0.3 * p.loadingTime(), 1.2 * p.loadingTime()};
        const std::string where = std::string(law) + " " + name(integrator) + " theta " + std::to_string(c.theta) +
                                  " sigma " + std::to_string(c.sigma);
        p.skipIdle = true;
        const Result skipped = simulate(p, c.grading, q, {7, 1, 3});
        p.skipIdle = false;
        const Result stepped = simulate(p, c.grading, q, {7, 1, 3});
        ASSERT_TRUE(stepped.friction.peakConfirmed) << where;
        expectSameResults(skipped, stepped, where);
      }
    }
  }
}

TEST(SkipIdle, TheJumpEndsAtTheFirstSlip) {
  // The quiet phase really is skipped (a large share of the loading) and ends at the step of
  // the first slip: one step later some block has slipped, and not before.
  const Grading g = graded(GradingProfile::Linear, GradedProperty::Both, 0.2);
  Parameters p = sbm::testing::paperParameters(16, 0.028, g);
  const auto stiffness = buildStiffness(p, g);
  const auto friction = buildFriction(p, g, {1, 2, 3});
  const auto law = CoulombStickSlip::make(friction, p.frictionLaw);
  FastLattice<CoulombStickSlip> lattice(stiffness, law, motionOf(p, p.timeStep, p.damping));
  Motion stepped = motionOf(p, p.timeStep, p.damping);
  stepped.skipIdle = false;
  FastLattice<CoulombStickSlip> reference(stiffness, law, stepped);
  EXPECT_EQ(reference.quietSteps(), 0);
  const std::int64_t quiet = lattice.quietSteps();
  EXPECT_GT(double(quiet) * p.timeStep, 0.5 * p.loadingTime());
  for (std::int64_t n = 0; n < quiet; ++n) {
    reference.step();
    ASSERT_EQ(reference.slippedBlocks(), 0) << n;
  }
  reference.step();
  EXPECT_GT(reference.slippedBlocks(), 0);
}

TEST(SkipIdle, AUniformPlateSlipsEverywhereAtOnce) {
  // sigma = 0, no grading: every block has the same slider and the same threshold, so all of them
  // start to slip at the same predicted step, K_s v t_n > mu_s F_n.
  Parameters p = sbm::testing::paperParameters(10, 0.0);
  const auto stiffness = buildStiffness(p, {});
  const auto friction = buildFriction(p, {}, {});
  ASSERT_EQ(friction.layout, SiteLayout::Uniform);
  FastLattice<CoulombStickSlip> lattice(stiffness, CoulombStickSlip::make(friction, p.frictionLaw),
                                        motionOf(p, p.timeStep, p.damping));
  const std::int64_t first = lattice.quietSteps();
  const double threshold = friction.staticStrength[0], k = stiffness.slider[0], v = p.plate.velocity;
  const double crossing = threshold / (k * v * p.timeStep);  // K_s v t = mu_s F_n, in steps
  EXPECT_GE(double(first), crossing - 1e-6);
  EXPECT_LT(double(first), crossing + 1.0 + 1e-6);
  while (lattice.steps() < first) lattice.step();
  EXPECT_EQ(lattice.slippedBlocks(), 0);
  lattice.step();
  EXPECT_EQ(lattice.slippedBlocks(), 100);
}

TEST(SkipIdle, OneWeakBlockSlipsFirstAndAlone) {
  // A uniform plate with one block at 90 % of the others' static strength: the jump ends at that
  // block's step, and exactly one block is active after it.
  Parameters p = sbm::testing::paperParameters(10, 0.0);
  const auto stiffness = buildStiffness(p, {});
  const int weak = 4 * 10 + 6;
  const FrictionSites sites = withOneWeakBlock(p, weak);
  const double strong = sites.staticStrength[0];
  const Motion motion = motionOf(p, p.timeStep, p.damping);
  FastLattice<CoulombStickSlip> lattice(stiffness, CoulombStickSlip::make(sites, p.frictionLaw), motion);
  EXPECT_EQ(lattice.quietSteps(),
            firstSlipStepAtRest<CoulombStickSlip>(stiffness.slider[6], 0.9 * strong, motion, std::int64_t(1) << 52));
  std::vector<double> firstSlip(100, std::numeric_limits<double>::quiet_NaN());
  lattice.recordFirstSlips(firstSlip.data());
  while (lattice.steps() <= lattice.quietSteps()) lattice.step();
  EXPECT_EQ(lattice.slippedBlocks(), 1);
  EXPECT_EQ(lattice.blockStates()[weak], Slipping);
  EXPECT_EQ(firstSlip[weak], double(lattice.quietSteps()) * p.timeStep);
}

namespace {

// Steps a lattice with idle work skipped and one stepped over the whole plate side by side for
// `steps` steps: the slider forces and slip counts agree at every step, the states at the end,
// bit for bit. Returns the skipping lattice's counters.
template <class Law>
void expectActiveSetIsFullSweep(const Parameters& p, const Grading& g, std::int64_t steps, const std::string& where,
                                std::int64_t& activeSteps, std::int64_t& heldTileSteps, std::int64_t& quietSteps) {
  const auto stiffness = buildStiffness(p, g);
  const auto law = [&] {
    const FrictionField friction = buildFriction(p, g, {4, 4, 4});
    if constexpr (hasBlockState<Law>) return Law::make(friction, p.frictionLaw, std::size_t(p.blocksPerSide) * p.blocksPerSide);
    else return Law::make(friction, p.frictionLaw);
  }();
  FastLattice<Law> skipping(stiffness, law, motionOf(p, p.timeStep, p.damping));
  Motion full = motionOf(p, p.timeStep, p.damping);
  full.skipIdle = false;
  FastLattice<Law> stepped(stiffness, law, full);
  for (std::int64_t n = 0; n < steps; ++n) {
    const StepObservation a = skipping.step(), b = stepped.step();
    ASSERT_TRUE(sameBits(a.sliderForceX, b.sliderForceX) && sameBits(a.sliderForceY, b.sliderForceY)) << where << " step " << n;
    ASSERT_EQ(skipping.slippedBlocks(), stepped.slippedBlocks()) << where << " step " << n;
  }
  const std::size_t blocks = std::size_t(p.blocksPerSide) * p.blocksPerSide;
  const auto same = [&](const double* x, const double* y) {
    for (std::size_t i = 0; i < blocks; ++i)
      if (!sameBits(x[i], y[i])) return false;
    return true;
  };
  EXPECT_TRUE(same(skipping.displacementX(), stepped.displacementX())) << where;
  EXPECT_TRUE(same(skipping.displacementY(), stepped.displacementY())) << where;
  EXPECT_TRUE(same(skipping.velocityX(), stepped.velocityX())) << where;
  EXPECT_TRUE(same(skipping.velocityY(), stepped.velocityY())) << where;
  EXPECT_EQ(skipping.blockStates(), stepped.blockStates()) << where;
  if constexpr (hasBlockState<Law>) {  // the held blocks healed as the stepped ones
    EXPECT_TRUE(same(skipping.law().state.data(), stepped.law().state.data())) << where;
  }
  EXPECT_EQ(stepped.activeSetSteps(), 0) << where;
  EXPECT_EQ(stepped.heldTileSteps(), 0) << where;
  activeSteps = skipping.activeSetSteps();
  heldTileSteps = skipping.heldTileSteps();
  quietSteps = skipping.quietSteps();
}

}  // namespace

TEST(SkipIdle, TheActiveSetIsTheFullSweepBitForBit) {
  // Velocity Verlet on graded, dispersed plates wider than a few tiles: the active set runs while
  // the detachment front crosses (held tiles left out of the update), the full sweep once most
  // tiles move, and the states and slider forces stay those of the full sweep at every step, bit
  // for bit; for every law (the state law's held blocks heal while held), graded friction, E or
  // both, sliding along x or at an angle.
  struct Case {
    GradedProperty property;
    double delta, theta;
    const char* law;
  };
  const Case cases[] = {{GradedProperty::Friction, 0.4, 0.0, "coulomb"},
                        {GradedProperty::YoungsModulus, 0.4, 0.0, "coulomb"},
                        {GradedProperty::Both, -0.3, 30.0, "exponential"},
                        {GradedProperty::Friction, 0.9, 135.0, "coulomb"},
                        {GradedProperty::Both, 0.3, 0.0, "state"},
                        {GradedProperty::YoungsModulus, -0.4, 60.0, "state"}};
  for (const Case& c : cases) {
    const Grading g = graded(GradingProfile::Linear, c.property, c.delta);
    Parameters p = sbm::testing::paperParameters(30, 0.028, g);
    p.plate.slidingAngle = c.theta;
    p.frictionLaw.name = c.law;
    const std::int64_t steps = std::int64_t(1.5 * p.loadingTime() / p.timeStep);
    const std::string where = "delta " + std::to_string(c.delta) + " theta " + std::to_string(c.theta) + " " + c.law;
    std::int64_t active = 0, held = 0, quiet = 0;
    if (p.frictionLaw.name == "exponential")
      expectActiveSetIsFullSweep<ExponentialVelocityWeakening>(p, g, steps, where, active, held, quiet);
    else if (p.frictionLaw.name == "state")
      expectActiveSetIsFullSweep<StateWeakening>(p, g, steps, where, active, held, quiet);
    else
      expectActiveSetIsFullSweep<CoulombStickSlip>(p, g, steps, where, active, held, quiet);
    // Both sweeps were used: the active set after the first slip, the full sweep once most move;
    // and the active set held tiles.
    EXPECT_GT(active, 10) << where;
    EXPECT_LT(active, steps - quiet) << where;
    EXPECT_GT(held, 0) << where;
  }
}

TEST(SkipIdle, OneWeakBlockLeavesEveryOtherTileHeld) {
  // A uniform 40 x 40 plate (5 tiles of 8 per row, 200 tiles) with one weak block inside: at its
  // first slip the active set starts, evaluates every tile once and proves that the others hold.
  // In the next step exactly the 3 x 3 tiles around the weak block's tile are updated, the other
  // 191 are held; and the run stays the full sweep's bit for bit.
  Parameters p = sbm::testing::paperParameters(40, 0.0);
  p.integrator = Integrator::VelocityVerlet;
  const auto stiffness = buildStiffness(p, {});
  const FrictionSites sites = withOneWeakBlock(p, 20 * 40 + 20);  // row 20, column 20: tile 2 of row 20
  Motion motion = motionOf(p, p.timeStep, p.damping);
  motion.integrator = Integrator::VelocityVerlet;
  FastLattice<CoulombStickSlip> lattice(stiffness, CoulombStickSlip::make(sites, p.frictionLaw), motion);
  Motion full = motion;
  full.skipIdle = false;
  FastLattice<CoulombStickSlip> stepped(stiffness, CoulombStickSlip::make(sites, p.frictionLaw), full);
  ASSERT_EQ(FastLattice<CoulombStickSlip>::kTile, 8);
  while (lattice.steps() <= lattice.quietSteps()) lattice.step();  // the first slip's step
  EXPECT_EQ(lattice.slippedBlocks(), 1);
  EXPECT_EQ(lattice.activeSetSteps(), 1);
  EXPECT_EQ(lattice.heldTileSteps(), 0);  // the first active step evaluates every tile
  lattice.step();
  EXPECT_EQ(lattice.heldTileSteps(), 200 - 9);
  while (stepped.steps() < lattice.steps()) stepped.step();
  for (int n = 0; n < 200; ++n) {
    const StepObservation a = lattice.step(), b = stepped.step();
    ASSERT_TRUE(sameBits(a.sliderForceX, b.sliderForceX) && sameBits(a.sliderForceY, b.sliderForceY)) << n;
    ASSERT_EQ(lattice.slippedBlocks(), stepped.slippedBlocks()) << n;
  }
  EXPECT_EQ(std::vector<double>(lattice.displacementX(), lattice.displacementX() + 1600),
            std::vector<double>(stepped.displacementX(), stepped.displacementX() + 1600));
  EXPECT_GT(lattice.heldTileSteps(), 191 * 10);
}

TEST(SkipIdle, TheHardCasesAreTheFullSweepBitForBit) {
  // The hard cases of test_hard_cases.cpp with velocity Verlet, idle work skipped (the jump, the
  // active set and its held tiles) against every block stepped: |Delta| = 0.9, sigma = 30 %, no
  // damping, a step at 0.9 of the stability limit. Bit for bit at every step; every case holds
  // tiles (24 x 24 plates: 870-255,000 held tile-steps).
  struct Case {
    const char* name;
    Grading grading;
    double sigma, dtSafety, dampingFactor;
  };
  const Case cases[] = {{"Delta = 0.9", graded(GradingProfile::Linear, GradedProperty::Friction, 0.9), 0.028, 0.0, 0.1},
                        {"Delta = -0.9 (E)", graded(GradingProfile::Linear, GradedProperty::YoungsModulus, -0.9), 0.028, 0.0, 0.1},
                        {"sigma = 30 %", {}, 0.3, 0.0, 0.1},
                        {"gamma = 0", graded(GradingProfile::Linear, GradedProperty::Friction, 0.2), 0.028, 0.0, 0.0},
                        {"dt = 0.9 limit", graded(GradingProfile::Linear, GradedProperty::Friction, 0.2), 0.028, 0.9, 0.1}};
  for (const Case& c : cases) {
    Parameters p = sbm::testing::paperParameters(24, c.sigma, c.grading, c.dtSafety, c.dampingFactor);
    p.integrator = Integrator::VelocityVerlet;
    const std::int64_t steps = std::int64_t(1.5 * p.loadingTime() / p.timeStep);
    std::int64_t active = 0, held = 0, quiet = 0;
    expectActiveSetIsFullSweep<CoulombStickSlip>(p, c.grading, steps, c.name, active, held, quiet);
    EXPECT_GT(quiet, 0) << c.name;
    EXPECT_GT(active, 0) << c.name;
    EXPECT_GT(held, 0) << c.name;  // the held tiles ran
  }
}
