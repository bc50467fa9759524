// The state law (physics/state_weakening_law.hpp) on its own, against its closed forms:
// * its steady state at any slip rate is the paper's Eq. 1 (the exponential law's value);
// * a site pulled at a constant fast rate weakens over D_c of slip with the law's shape, exactly
//   whatever the step;
// * a site at rest heals as theta e^(-v_c t / D_c);
// * nothing changes before commit(); a site that never slid holds mu_s.
// And the process-zone measure (physics/process_zone.hpp) on synthetic fronts of known width.
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/process_zone.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;

namespace {

constexpr double kMuS = 1.0, kMuK = 0.6, kVc = 1e-4, kDc = 5e-8;

StateWeakening stateLaw(double slipLength = kDc) {
  FrictionSites sites{SiteLayout::PerSite, 2, {kMuS, 1.3}, {kMuK, 0.7}};
  FrictionLawSettings settings{"state", kVc, slipLength};
  return StateWeakening::make(sites, settings, 2);
}

}  // namespace

TEST(StateLaw, SteadyStateIsEquationOne) {
  const ExponentialVelocityWeakening eq1 = ExponentialVelocityWeakening::make(
      {SiteLayout::PerSite, 2, {kMuS, 1.3}, {kMuK, 0.7}}, FrictionLawSettings{"exponential", kVc, kDc});
  for (int site = 0; site < 2; ++site)
    for (double v : {0.0, 1e-6, 3e-5, 1e-4, 4e-4, 1e-3, 0.1}) {
      StateWeakening law = stateLaw();
      // Slide at v until the state has settled (many relaxation times D_c / v_c).
      for (int i = 0; i < 200; ++i) {
        law.advance(site, v * 1e-3, 1e-3);
        law.commit();
      }
      const double expected = eq1.slidingStrength(eq1.sites.staticAt(site), eq1.sites.kineticAt(site), v);
      EXPECT_NEAR(law.strengthAt(site, law.state[site]), expected, 1e-14) << "site " << site << ", v " << v;
      EXPECT_NEAR(law.steadyStrength(site, v), expected, 1e-15);
    }
}

TEST(StateLaw, FastSlipWeakensOverTheSlipLengthWhateverTheStep) {
  const double v = 1e3 * kVc;  // the slip rate behind a front
  for (int steps : {1, 7, 100}) {
    StateWeakening law = stateLaw();
    EXPECT_EQ(law.strengthAt(0, law.state[0]), kMuS);  // never slid: mu_s
    for (double slip = 0; slip < 6 * kDc - 1e-20; slip += kDc) {
      for (int i = 0; i < steps; ++i) {
        law.advance(0, kDc / steps, kDc / steps / v);
        law.commit();
      }
      const double s = slip + kDc;
      // theta(s) for constant v from 0, in closed form; mu falls by e at each D_c while v >> v_c.
      const double theta = v * kDc / kVc * (1.0 - std::exp(-kVc * s / (v * kDc)));
      const double mu = kMuK + (kMuS - kMuK) * std::exp(-theta / kDc);
      EXPECT_NEAR(law.strengthAt(0, law.state[0]), mu, 1e-13) << steps << " steps per D_c, slip " << s;
      EXPECT_NEAR(theta / s, 1.0, 0.01);  // slip weakening: theta is the slip
    }
    // After 6 D_c the site is within 0.3 % of Delta mu from mu_k.
    EXPECT_LT(law.strengthAt(0, law.state[0]) - kMuK, 0.003 * (kMuS - kMuK));
  }
}

TEST(StateLaw, ASiteAtRestHeals) {
  StateWeakening law = stateLaw();
  for (int i = 0; i < 10; ++i) {  // weaken: 10 D_c at 0.1 m/s
    law.advance(0, kDc, kDc / 0.1);
    law.commit();
  }
  const double theta0 = law.state[0];
  ASSERT_LT(law.strengthAt(0, theta0), kMuK + 0.01);
  const double healing = kDc / kVc;  // the healing time
  double t = 0;
  for (double dt : {0.1 * healing, 0.4 * healing, 1.5 * healing}) {
    law.advance(0, 0.0, dt);
    law.commit();
    t += dt;
    EXPECT_NEAR(law.state[0], theta0 * std::exp(-t / healing), 1e-12 * theta0);
  }
  EXPECT_GT(law.strengthAt(0, law.state[0]), kMuK + 0.01);  // stronger again
}

TEST(StateLaw, NothingChangesBeforeCommit) {
  StateWeakening law = stateLaw();
  const double weakened = law.advance(1, 1e-7, 1e-6);
  EXPECT_LT(weakened, 1.3);
  EXPECT_EQ(law.state[1], 0.0);                   // committed state unchanged
  EXPECT_EQ(law.strengthAt(1, law.state[1]), 1.3);  // site 1's own mu_s
  law.commit();
  EXPECT_EQ(law.strengthAt(1, law.state[1]), weakened);
  EXPECT_EQ(describeFrictionLaw(FrictionLawSettings{"state", kVc, kDc}).find("D_c") != std::string::npos, true);
}

TEST(ProcessZone, AStraightFrontOfKnownWidth) {
  // A front along x at speed c, weakening over tau: Lambda = c tau, on a uniform and a graded grid.
  const double c = 50.0, tau = 4e-7;  // Lambda = 20 um
  for (bool graded : {false, true}) {
    std::vector<double> lines;
    double x = 0;
    for (int i = 0; i <= 200; ++i) {
      lines.push_back(x);
      x += graded && i < 50 ? 2e-6 : 5e-6;  // 2 um cells near x = 0, 5 um beyond
    }
    WeakeningTimes t;
    for (int j = 0; j < 5; ++j)
      for (double xi : lines) {
        t.x.push_back(xi);
        t.y.push_back(1e-5 * j);
        t.start.push_back(xi / c);
        t.end.push_back(xi / c + tau);
      }
    const ProcessZone zone = measureProcessZone(t, 1.0);
    EXPECT_EQ(zone.nodes, 5 * 201);
    EXPECT_NEAR(zone.median, c * tau, 1e-9 * c * tau);
    EXPECT_NEAR(zone.medianElements, c * tau / 5e-6, 1e-6);  // most cells are 5 um
    EXPECT_NEAR(zone.lowElements, c * tau / 5e-6, 1e-6);  // the coarsest cells are the worst resolved
    if (graded) {  // the zone over the 2 um cells alone: 2.5 times more elements
      const ProcessZone fine = measureProcessZone(t, lines[40] / c);
      EXPECT_NEAR(fine.medianElements, c * tau / 2e-6, 1e-6);
    }
    // Only the nodes whose weakening started by the given time count.
    EXPECT_LT(measureProcessZone(t, lines[100] / c).nodes, 5 * 102);
  }
  // Nodes that never finished weakening, or a plate that weakened everywhere at once, give nothing.
  WeakeningTimes none{{0, 1e-6}, {0, 0}, {1e-6, 1e-6}, {-1, -1}};
  EXPECT_EQ(measureProcessZone(none, 1.0).nodes, 0);
}
