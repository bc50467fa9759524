// Hard cases a design study reaches (issue: "hard cases stay numerically stable"). Each run must
// stay finite, keep kinetic + elastic energy below the slider's work (the run's own monitor
// throws otherwise), keep mu(t) between 0 and the largest local mu_s, and agree with the same
// case at half the time step.
#include "sbm_support.hpp"
#include "gradfric/physics/stability.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

struct HardCase {
  std::string name;
  Grading grading;
  int blocks = 20;
  double sigma = 0.028;
  double theta = 0.0;
  double dtSafety = 0.0;  // 0: the shipped default step; else this fraction of the stability limit
  double dampingFactor = 0.1;
  Integrator integrator = Integrator::RK4;
  bool peakOnly = false;
};


Result run(const HardCase& c, double dtScale, double endTime = 0.0) {
  Parameters p = sbm::testing::paperParameters(c.blocks, c.sigma, c.grading, 0.25, c.dampingFactor);
  p.integrator = c.integrator;
  p.plate.slidingAngle = c.theta;
  p.timeStep = (c.dtSafety > 0 ? c.dtSafety * stableTimeStep(p, c.grading) : defaultTimeStep(p, c.grading)) * dtScale;
  Request q = sbm::testing::defaultRequest(p);
  q.measurement.kinetic = !c.peakOnly;
  q.energyCheckInterval = 50;
  q.endTime = endTime;
  return simulate(p, c.grading, q, {21, 0, 0});
}

double loadingTime() { return Parameters{}.loadingTime(); }

// Mean of the mu(t) history over [from, to].
double windowMean(const Result& r, double from, double to) {
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < r.friction.time.size(); ++i)
    if (r.friction.time[i] >= from && r.friction.time[i] <= to) {
      sum += r.friction.mu[i];
      ++count;
    }
  return sum / count;
}

void checkHardCase(const HardCase& c, double staticTolerance, double kineticTolerance) {
  SCOPED_TRACE(c.name);
  const Result a = run(c, 1.0);
  const Result b = run(c, 0.5);
  for (const Result* r : {&a, &b}) {
    ASSERT_TRUE(std::isfinite(r->friction.muStatic));
    EXPECT_TRUE(r->friction.peakConfirmed);
    for (double mu : r->friction.mu) {
      ASSERT_TRUE(std::isfinite(mu));
      ASSERT_GE(mu, 0.0);
      ASSERT_LE(mu, r->maxLocalStatic * (1 + 1e-9));
    }
    EXPECT_LE(r->energy, r->sliderWork * 1.001 + 1e-30);
  }
  EXPECT_NEAR(a.friction.muStatic, b.friction.muStatic, staticTolerance * b.friction.muStatic);
  if (c.peakOnly) return;
  if (std::fabs(a.friction.peakTime - b.friction.peakTime) < 0.1 * loadingTime()) {
    EXPECT_NEAR(a.friction.muKinetic, b.friction.muKinetic, kineticTolerance * b.friction.muKinetic);
  } else {
    // No static peak (large |Delta|: mu(t) rises to a plateau, as the paper describes): the peak
    // time, and the mu_k window placed after it, are ill-defined. Compare the kinetic level over
    // one fixed window at the end of runs of equal length instead.
    const double end = std::max(a.endTime, b.endTime);
    const double from = end - loadingTime();
    const double levelA = windowMean(run(c, 1.0, end), from, end);
    const double levelB = windowMean(run(c, 0.5, end), from, end);
    EXPECT_NEAR(levelA, levelB, kineticTolerance * levelB) << "fixed window [" << from << ", " << end << "] s";
  }
}

}  // namespace

TEST(HardCases, LargeGradingAmplitudeBothModelsOfGrading) {
  for (auto property : {GradedProperty::YoungsModulus, GradedProperty::Friction, GradedProperty::Both})
    for (auto profile : {GradingProfile::Linear, GradingProfile::Triangular})
      for (double delta : {0.9, -0.9}) {
        HardCase c{std::string(toString(property)) + " " + toString(profile) + " Delta=" + std::to_string(delta),
                   sbm::testing::grading(profile, property, delta)};
        // 2 %: at |Delta| = 0.9 the order of slip events scatters mu_s with the step; measured on
        // E linear +0.9 at 1, 1/2, 1/4, 1/8 of the step: 0.6591, 0.6695, 0.6657, 0.6607.
        checkHardCase(c, 0.02, 0.02);
      }
}

TEST(HardCases, LargeDispersion) { checkHardCase({"sigma = 30 %", {}, 20, 0.3}, 0.01, 0.02); }

TEST(HardCases, OneBandPerBlockColumn) {
  checkHardCase({"N = N_b", sbm::testing::grading(GradingProfile::Linear, GradedProperty::Both, 0.5, 20)}, 0.01, 0.02);
}

TEST(HardCases, SlidingAtNinetyDegrees) {
  HardCase c{"theta = 90", sbm::testing::grading(GradingProfile::Linear, GradedProperty::Friction, 0.4)};
  c.theta = 90.0;
  checkHardCase(c, 0.01, 0.02);
}

TEST(HardCases, TimeStepAtNineTenthsOfTheStabilityLimit) {
  // On the paper's lattice, where the stability limit is about half the slip time sqrt(m/K_s).
  // (On coarse lattices the limit exceeds the slip time: stable, but too coarse to be accurate,
  // which is why the default step is also capped by the slip time.)
  for (auto integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    HardCase c{"dt = 0.9 limit", sbm::testing::grading(GradingProfile::Linear, GradedProperty::YoungsModulus, 0.5)};
    c.blocks = 120;
    c.dtSafety = 0.9;
    c.integrator = integrator;
    c.peakOnly = true;
    // Stable, bounded and physical; but slip events make every scheme first order in dt, and at
    // half the slip time the peak moves by a few per cent against dt/2 (measured: RK4 4.2 %,
    // Verlet 2.1 % on this case). The shipped default step is five times smaller.
    checkHardCase(c, 0.05, 0.0);
  }
}

TEST(HardCases, NoDampingAtAll) {
  HardCase c{"gamma = 0", sbm::testing::grading(GradingProfile::Triangular, GradedProperty::Friction, 0.3)};
  c.dampingFactor = 0.0;
  checkHardCase(c, 0.01, 0.03);
}

TEST(HardCases, PaperSizeLatticeTwiceOver) {
  HardCase c{"240 x 240", sbm::testing::grading(GradingProfile::Linear, GradedProperty::Friction, 0.3)};
  c.blocks = 240;
  c.integrator = Integrator::VelocityVerlet;
  c.peakOnly = true;
  checkHardCase(c, 0.01, 0.0);
}

TEST(HardCases, AnUnstableRunIsStoppedByTheMonitor) {
  // Past the stability limit (only possible by bypassing the option check) the run must stop at
  // once with a message naming the quantity that blew up and the likely cause.
  for (auto integrator : {Integrator::RK4, Integrator::VelocityVerlet}) {
    for (double factor : {1.3, 2.0, 3.0}) {
      Parameters p = sbm::testing::paperParameters(16, 0.028);
      p.integrator = integrator;
      p.timeStep = factor * stableTimeStep(p, {});
      Request q = sbm::testing::defaultRequest(p);
      try {
        const Result r = simulate(p, {}, q, {1, 0, 0});
        // Slightly past the limit the unstable modes may not grow within the run: then the
        // result must still be physical.
        EXPECT_LE(r.friction.muStatic, 2 * r.maxLocalStatic) << factor;
        EXPECT_LE(r.energy, r.sliderWork * 1.001) << factor;
        EXPECT_LT(factor, 2.0) << "no instability detected at " << factor << " x the limit";
      } catch (const gradfric::NumericalInstability& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("unstable"), std::string::npos) << message;
        EXPECT_TRUE(message.find("energy") != std::string::npos || message.find("mu(t)") != std::string::npos)
            << message;
        EXPECT_NE(message.find("stability limit"), std::string::npos) << message;
      }
    }
  }
}
