// Spring stiffness per block (an E field that varies along y, lattice.hpp): built per block, an E
// that is constant along y is the per-column lattice bit for bit on every kernel path; the fast
// kernel agrees with the plain reference on E fields that vary along y, and its instruction-set
// versions agree bit for bit, as does the quiet-phase jump with the stepped run; the 90-degree E
// grading slid at 90 degrees is the 0-degree case transposed; the first block to slip is the one
// with the stiffest slider; the load-dependent pressure keeps its force and moment balance.
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "gradfric/sbm/kernel_isa.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameBits(const double* a, const double* b, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!sameBits(a[i], b[i])) return false;
  return true;
}

PropertyField linearE(double delta, double angle, int bands = 0) {
  PropertyField f;
  f.shape = FieldShape::Linear;
  f.delta = delta;
  f.angle = angle;
  f.bands = bands;
  f.length = Plate{}.length;
  return f;
}

// Stiffer at the plate's centre, softer towards the corners.
PropertyField radialE(double delta) {
  PropertyField f;
  f.shape = FieldShape::Linear;
  f.delta = -delta;
  f.radial = true;
  f.length = Plate{}.length;
  f.centreX = f.centreY = 0.5 * f.length;
  return f;
}

Grading withE(const PropertyField& f) {
  PlateFields fields;
  fields.modulus = std::make_shared<const PropertyField>(f);
  Grading g;
  g.fields = std::make_shared<const PlateFields>(fields);
  return g;
}

const char* name(Integrator integrator) { return integrator == Integrator::RK4 ? "rk4" : "verlet"; }

}  // namespace

TEST(PerBlockStiffness, BuildsTheSeriesRuleForEveryPair) {
  const Grading g = withE(radialE(0.4));
  const Parameters p = sbm::testing::paperParameters(6, 0.0, g);
  const LatticeStiffness s = buildStiffness(p, g);
  ASSERT_TRUE(s.perBlock && s.graded);
  const BlockProperties b = blockProperties(p, g);
  auto k = [&](int r, int c) { return p.axialStiffness(b.modulus[r * 6 + c]); };
  auto series = [](double a, double c) { return 2 * a * c / (a + c); };
  for (int r = 0; r < 6; ++r) {
    const RowStiffness row = s.row(r);
    for (int c = 0; c < 6; ++c) {
      EXPECT_DOUBLE_EQ(row.slider[c], p.sliderStiffness(b.modulus[r * 6 + c]));
      if (c + 1 < 6) {
        EXPECT_DOUBLE_EQ(row.horizontal[c], series(k(r, c), k(r, c + 1)));
      }
      if (r + 1 == 6) continue;
      EXPECT_DOUBLE_EQ(row.vertical[c], series(k(r, c), k(r + 1, c)));
      if (c + 1 < 6) {
        EXPECT_DOUBLE_EQ(row.diagonal[c], series(0.5 * k(r, c), 0.5 * k(r + 1, c + 1)));
        EXPECT_DOUBLE_EQ(row.antiDiagonal[c], series(0.5 * k(r, c + 1), 0.5 * k(r + 1, c)));
      }
    }
  }
  // An E along x only stays per column; at 90 degrees it varies along y: per block.
  EXPECT_FALSE(buildStiffness(p, withE(linearE(0.2, 0))).perBlock);
  EXPECT_TRUE(buildStiffness(p, withE(linearE(0.2, 90))).perBlock);
}

TEST(PerBlockStiffness, AnEConstantAlongYIsThePerColumnLatticeBitForBit) {
  // The same E along x, once per column and once forced per block: every slider force, state
  // and displacement the same bits at every step, for both integrators, with the quiet-phase jump
  // and the active set (a plate wider than a few tiles) and without; on the plain reference too.
  for (const Grading& g : {Grading{GradingProfile::Linear, GradedProperty::Both, 0.4, 10}, withE(linearE(-0.3, 0))}) {
    for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
      Parameters p = sbm::testing::paperParameters(24, 0.028, g);
      p.integrator = integrator;
      p.timeStep = defaultTimeStep(p, g);
      const LatticeStiffness columns = buildStiffness(p, g), blocks = buildStiffness(p, g, true);
      ASSERT_FALSE(columns.perBlock);
      ASSERT_TRUE(blocks.perBlock);
      const auto law = CoulombStickSlip::make(buildFriction(p, g, {4, 2, 1}), p.frictionLaw);
      const std::int64_t steps = std::int64_t(1.4 * p.loadingTime() / p.timeStep);
      const std::size_t n = 24 * 24;
      for (bool skipIdle : {true, false}) {
        Motion motion = motionOf(p, p.timeStep, p.damping);
        motion.skipIdle = skipIdle;
        FastLattice<CoulombStickSlip> a(columns, law, motion), b(blocks, law, motion);
        for (std::int64_t step = 0; step < steps; ++step) {
          const StepObservation x = a.step(), y = b.step();
          ASSERT_TRUE(sameBits(x.sliderForceX, y.sliderForceX) && sameBits(x.sliderForceY, y.sliderForceY))
              << name(integrator) << " skip " << skipIdle << " step " << step;
        }
        const std::string where = std::string(name(integrator)) + (skipIdle ? " skipping idle work" : " stepped");
        EXPECT_GT(a.slippedBlocks(), 0) << where;
        EXPECT_EQ(a.slippedBlocks(), b.slippedBlocks()) << where;
        EXPECT_TRUE(sameBits(a.displacementX(), b.displacementX(), n)) << where;
        EXPECT_TRUE(sameBits(a.displacementY(), b.displacementY(), n)) << where;
        EXPECT_TRUE(sameBits(a.velocityX(), b.velocityX(), n)) << where;
        EXPECT_EQ(a.activeSetSteps(), b.activeSetSteps()) << where;
        if (skipIdle && integrator == Integrator::VelocityVerlet) {
          EXPECT_GT(b.activeSetSteps(), 0) << where;
        }
        // Energies and stresses read the same springs.
        const LatticeEnergy ea = latticeEnergy(columns, p.blockMass(), a.displacementX(), a.displacementY(),
                                               a.velocityX(), a.velocityY(), 0.0, 0.0);
        const LatticeEnergy eb = latticeEnergy(blocks, p.blockMass(), a.displacementX(), a.displacementY(),
                                               a.velocityX(), a.velocityY(), 0.0, 0.0);
        EXPECT_TRUE(sameBits(ea.internal, eb.internal) && sameBits(ea.slider, eb.slider)) << where;
        std::vector<double> sa(n), sb(n);
        longitudinalStress(columns, p.layerThickness, p.plate.pressure, a.displacementX(), a.displacementY(), sa.data());
        longitudinalStress(blocks, p.layerThickness, p.plate.pressure, a.displacementX(), a.displacementY(), sb.data());
        EXPECT_TRUE(sameBits(sa.data(), sb.data(), n)) << where;
      }
    }
  }
  // The plain reference, on a smaller plate.
  const Grading g = withE(linearE(0.4, 180));
  const Parameters p = sbm::testing::paperParameters(8, 0.028, g);
  const auto law = CoulombStickSlip::make(buildFriction(p, g, {4, 2, 1}), p.frictionLaw);
  const Motion motion = motionOf(p, p.timeStep, p.damping);
  ReferenceLattice<CoulombStickSlip> a(buildStiffness(p, g), law, motion), b(buildStiffness(p, g, true), law, motion);
  const std::int64_t steps = std::int64_t(1.4 * p.loadingTime() / p.timeStep);
  for (std::int64_t step = 0; step < steps; ++step) {
    const StepObservation x = a.step(), y = b.step();
    ASSERT_TRUE(sameBits(x.sliderForceX, y.sliderForceX) && sameBits(x.sliderForceY, y.sliderForceY)) << step;
  }
  EXPECT_GT(a.slippedBlocks(), 0);
  EXPECT_EQ(a.displacementX(), b.displacementX());
}

TEST(PerBlockStiffness, TheFastKernelIsThePlainReferenceOnEFieldsAlongY) {
  // A 45-degree linear E and a radial E, both integrators, with dispersion and without: mu(t)
  // to round-off, the same first-slip map.
  for (const PropertyField& field : {linearE(0.4, 45), radialE(0.4)}) {
    const Grading g = withE(field);
    for (Integrator integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
      for (double sigma : {0.0, 0.05}) {
        Parameters p = sbm::testing::paperParameters(10, sigma, g);
        p.integrator = integrator;
        p.timeStep = defaultTimeStep(p, g);
        p.plate.slidingAngle = 30.0;
        const std::string where = std::string(field.radial ? "radial " : "45 degrees ") + name(integrator) +
                                  " sigma " + std::to_string(sigma);
        const Request q = sbm::testing::defaultRequest(p);
        const Result fast = simulate(p, g, q, {3, 1, 2}, Kernel::Fast);
        const Result plain = simulate(p, g, q, {3, 1, 2}, Kernel::Reference);
        ASSERT_TRUE(fast.friction.peakConfirmed) << where;
        ASSERT_EQ(fast.friction.mu.size(), plain.friction.mu.size()) << where;
        for (std::size_t i = 0; i < fast.friction.mu.size(); ++i)
          ASSERT_NEAR(fast.friction.mu[i], plain.friction.mu[i], 1e-9 * (1 + plain.friction.mu[i])) << where << " " << i;
        EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, 1e-10) << where;
        ASSERT_EQ(fast.firstSlipTime.size(), plain.firstSlipTime.size());
        for (std::size_t i = 0; i < fast.firstSlipTime.size(); ++i)
          EXPECT_EQ(fast.firstSlipTime[i], plain.firstSlipTime[i]) << where << " block " << i;
      }
    }
  }
}

TEST(PerBlockStiffness, TheQuietPhaseJumpIsTheSteppedRunBitForBit) {
  // The jump predicts the first slip from each block's own slider K_s,i: with E along y it ends
  // where the stepped run's first slip is, and the run is the same bits (Verlet with the active
  // set, and RK4).
  for (const PropertyField& field : {linearE(0.4, 45), radialE(-0.3)}) {
    const Grading g = withE(field);
    for (Integrator integrator : {Integrator::VelocityVerlet, Integrator::RK4}) {
      Parameters jump = sbm::testing::paperParameters(20, 0.028, g);
      jump.integrator = integrator;
      jump.timeStep = defaultTimeStep(jump, g);
      Parameters stepped = jump;
      stepped.skipIdle = false;
      const Request q = sbm::testing::defaultRequest(jump);
      const Result a = simulate(jump, g, q, {5, 0, 2}), b = simulate(stepped, g, q, {5, 0, 2});
      const std::string where = std::string(field.radial ? "radial " : "45 degrees ") + name(integrator);
      ASSERT_EQ(a.friction.mu.size(), b.friction.mu.size()) << where;
      EXPECT_TRUE(sameBits(a.friction.mu.data(), b.friction.mu.data(), a.friction.mu.size())) << where;
      EXPECT_TRUE(sameBits(a.firstSlipTime.data(), b.firstSlipTime.data(), a.firstSlipTime.size())) << where;
      EXPECT_EQ(a.steps, b.steps) << where;
      EXPECT_GT(a.friction.firstSlipTime, 0.1 * jump.loadingTime()) << where << ": a quiet phase to jump over";
    }
  }
}

TEST(PerBlockStiffness, EveryKernelVersionGivesTheSameNumbersBitForBit) {
  // The per-block row pointers through every compiled instruction set the processor has: a radial
  // E, velocity Verlet with the active set and RK4.
  const Grading g = withE(radialE(0.4));
  std::vector<KernelIsa> versions;
  for (KernelIsa isa : {KernelIsa::Baseline, KernelIsa::Avx2, KernelIsa::Avx512})
    if (kernelIsaSupported(isa)) versions.push_back(isa);
  for (Integrator integrator : {Integrator::VelocityVerlet, Integrator::RK4}) {
    Parameters p = sbm::testing::paperParameters(24, 0.03, g);
    p.integrator = integrator;
    p.timeStep = defaultTimeStep(p, g);
    const Request q = sbm::testing::defaultRequest(p);
    std::vector<Result> results;
    for (KernelIsa isa : versions) {
      ASSERT_TRUE(forceKernelIsa(isa)) << kernelIsaName(isa);
      results.push_back(simulate(p, g, q, {7, 0, 1}, Kernel::Fast));
    }
    forceKernelIsa(KernelIsa::Automatic);
    const Result& base = results.front();
    ASSERT_TRUE(base.friction.peakConfirmed);
    for (std::size_t v = 1; v < results.size(); ++v) {
      const std::string where = std::string(name(integrator)) + ", " + kernelIsaName(versions[v]) + " against baseline";
      ASSERT_EQ(results[v].friction.mu.size(), base.friction.mu.size()) << where;
      EXPECT_TRUE(sameBits(results[v].friction.mu.data(), base.friction.mu.data(), base.friction.mu.size())) << where;
      EXPECT_TRUE(sameBits(results[v].firstSlipTime.data(), base.firstSlipTime.data(), base.firstSlipTime.size()))
          << where;
    }
  }
}

TEST(PerBlockStiffness, NinetyDegreesIsTheZeroDegreeCaseTransposed) {
  // E graded along y, slid along y, is E graded along x slid along x with x and y swapped: the
  // lattice is symmetric under the swap. The 0-degree plate runs per column, the 90-degree one
  // per block (the swap turns horizontal springs into vertical ones): the same mu(t) and first-slip
  // map to round-off. N_b = 16 keeps the block centres exact in both coordinates.
  const int nb = 16;
  for (double delta : {0.3, -0.3}) {
    const Grading along = withE(linearE(delta, 0, 4)), across = withE(linearE(delta, 90, 4));
    Parameters p = sbm::testing::paperParameters(nb, 0.0, along);
    const Request q = sbm::testing::defaultRequest(p);
    Parameters turned = p;
    turned.plate.slidingAngle = 90.0;
    const Result a = simulate(p, along, q, {1, 0, 0});
    const Result b = simulate(turned, across, q, {1, 0, 0});
    ASSERT_FALSE(buildStiffness(p, along).perBlock);
    ASSERT_TRUE(buildStiffness(turned, across).perBlock);
    ASSERT_TRUE(a.friction.peakConfirmed);
    EXPECT_NEAR(b.friction.muStatic, a.friction.muStatic, 1e-9 * a.friction.muStatic) << delta;
    const std::size_t loading = std::min(a.friction.mu.size(), b.friction.mu.size());
    ASSERT_GT(loading, 10u);
    for (std::size_t i = 0; i < std::size_t(0.9 * double(loading)); ++i)
      ASSERT_NEAR(b.friction.mu[i], a.friction.mu[i], 1e-9) << delta << " " << i;
    int compared = 0;
    for (int r = 0; r < nb; ++r)
      for (int c = 0; c < nb; ++c) {
        const double x = a.firstSlipTime[r * nb + c], y = b.firstSlipTime[c * nb + r];
        if (std::isnan(x) && std::isnan(y)) continue;
        EXPECT_NEAR(y, x, 2.0 * p.timeStep) << delta << " block " << r << "," << c;
        ++compared;
      }
    EXPECT_GT(compared, nb * nb / 2);
  }
}

TEST(PerBlockStiffness, TheStiffestSliderSlipsFirst) {
  // sigma = 0, uniform friction: at rest block i carries K_s,i v t alone, so the first blocks to
  // slip are those with the largest E: the stiff corner of a 45-degree grading (x = y = L at
  // Delta > 0, the origin at Delta < 0) and the centre of the radial one.
  const int nb = 12;
  struct Case {
    PropertyField field;
    int row, column;
  };
  const Case cases[] = {{linearE(0.3, 45), nb - 1, nb - 1}, {linearE(-0.3, 45), 0, 0}, {radialE(0.3), -1, -1}};
  for (const Case& c : cases) {
    const Grading g = withE(c.field);
    const Parameters p = sbm::testing::paperParameters(nb, 0.0, g);
    const Result r = simulate(p, g, sbm::testing::defaultRequest(p), {1, 0, 0});
    const LatticeStiffness s = buildStiffness(p, g);
    double earliest = INFINITY, stiffest = 0.0;
    for (double t : r.firstSlipTime) earliest = std::min(earliest, t);
    for (double k : s.slider) stiffest = std::max(stiffest, k);
    int first = 0;
    for (int i = 0; i < nb * nb; ++i) {
      if (s.slider[i] == stiffest) {
        EXPECT_EQ(r.firstSlipTime[i], earliest) << "the stiffest block " << i;
      }
      if (r.firstSlipTime[i] != earliest) continue;
      EXPECT_NEAR(s.slider[i], stiffest, 1e-9 * stiffest) << "block " << i << " slips first";
      const int row = i / nb, column = i % nb;
      if (c.row >= 0) {
        EXPECT_TRUE(row == c.row && column == c.column) << "block " << i;
      } else {
        EXPECT_TRUE((row == nb / 2 - 1 || row == nb / 2) && (column == nb / 2 - 1 || column == nb / 2)) << i;
      }
      ++first;
    }
    EXPECT_GE(first, 1);
  }
}

TEST(PerBlockStiffness, ThePressureCouplingKeepsItsBalances) {
  // The moment-balance pressure on a plate with a 45-degree E: the normal force stays p L^2 and
  // the moment H F at every step, on both kernels, and they agree.
  const Grading g = withE(linearE(0.3, 45));
  const auto [fast, plain] = sbm::testing::bothKernelsUnderMomentBalance(sbm::testing::paperParameters(12, 0.028, g), g);
  EXPECT_NEAR(fast.friction.muStatic, plain.friction.muStatic, 1e-10);
}
