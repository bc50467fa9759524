// The shared friction-history observer: peak rule, kinetic window, first slip, detachment time,
// sampling, known().
#include "gradfric/physics/friction_history.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;

namespace {

// A triangle: mu rises linearly to 1 at t = 1, falls to 0.5 at t = 2, then stays at 0.5.
double triangle(double t) { return t <= 1 ? t : t <= 2 ? 1.0 - 0.5 * (t - 1) : 0.5; }

FrictionMeasurement rule() {
  FrictionMeasurement m;
  m.peakDrop = 0.01;
  m.peakHold = 10.0;  // long: the drop confirms
  m.kineticDelay = 1.5;
  m.kineticWidth = 1.0;
  m.historyInterval = 0.0;
  return m;
}

}  // namespace

TEST(FrictionHistory, PeakConfirmedByTheDropOnceEverySiteSlipped) {
  const double dt = 0.01, normal = 2.0;
  FrictionHistory h(rule(), normal, dt);
  bool confirmedBeforeAllSlipped = false;
  for (int s = 0; s <= 400; ++s) {
    const double t = s * dt;
    // Every site has slipped only from t = 1.5 on: no confirmation before, although mu fell.
    h.observe(t, triangle(t) * normal, 0.0, t >= 0.5, t >= 1.5);
    if (t < 1.5 && h.peakConfirmed()) confirmedBeforeAllSlipped = true;
  }
  EXPECT_FALSE(confirmedBeforeAllSlipped);
  const FrictionSummary r = h.summary();
  EXPECT_TRUE(r.peakConfirmed);
  EXPECT_DOUBLE_EQ(r.muStatic, 1.0);
  EXPECT_NEAR(r.peakTime, 1.0, 1e-12);
  EXPECT_NEAR(r.firstSlipTime, 0.5, 1e-12);
  // Window [2.5, 3.5]: mu = 0.5 throughout.
  EXPECT_TRUE(r.kineticComplete);
  EXPECT_NEAR(r.muKinetic, 0.5, 1e-12);
}

TEST(FrictionHistory, DetachmentTimeIsTheFirstObservationWithEverySiteSlipped) {
  const double dt = 0.01;
  FrictionHistory h(rule(), 1.0, dt);
  // Reported true once at step 90, then false until step 137: the first true observation counts,
  // and what follows does not move it (the models' counts never fall, the observer need not rely on it).
  for (int s = 0; s <= 400; ++s) {
    const bool all = s >= 137 || s == 90;
    h.observe(s * dt, triangle(s * dt), 0.0, s >= 20, all);
  }
  const FrictionSummary r = h.summary();
  EXPECT_EQ(r.detachmentTime, 90 * dt);  // the observed time itself, not a rounded one
  EXPECT_EQ(r.firstSlipTime, 20 * dt);
}

TEST(FrictionHistory, DetachmentTimeIsNaNWhenSomeSiteNeverSlipped) {
  const double dt = 0.01;
  FrictionHistory h(rule(), 1.0, dt);
  for (int s = 0; s <= 400; ++s) h.observe(s * dt, triangle(s * dt), 0.0, s >= 20, false);
  const FrictionSummary r = h.summary();
  EXPECT_TRUE(std::isnan(r.detachmentTime));
  EXPECT_FALSE(r.peakConfirmed);  // the peak needs the whole plate to have slipped
  EXPECT_TRUE(std::isnan(FrictionHistory(rule(), 1.0, dt).summary().detachmentTime));  // nothing observed
}

TEST(FrictionHistory, ConfirmedPeakComesAtOrAfterTheDetachment) {
  // Every site has slipped only at t = 2.7, after the drop: the peak is confirmed at that very
  // observation, the detachment time.
  const double dt = 0.01;
  FrictionHistory h(rule(), 1.0, dt);
  int s = 0;
  for (; s <= 400 && !h.peakConfirmed(); ++s) h.observe(s * dt, triangle(s * dt), 0.0, true, s >= 270);
  const FrictionSummary r = h.summary();
  EXPECT_TRUE(r.peakConfirmed);
  EXPECT_EQ(r.detachmentTime, 270 * dt);
  EXPECT_EQ(s - 1, 270);
}

TEST(FrictionHistory, MuIsTheForceModulusOverTheNormalForce) {
  FrictionHistory h(rule(), 4.0, 0.1);
  EXPECT_DOUBLE_EQ(h.observe(0.0, 3.0, 4.0, false, false), 5.0 / 4.0);
  const FrictionSummary r = h.summary();
  ASSERT_EQ(r.forceX.size(), 1u);
  EXPECT_EQ(r.forceX[0], 3.0);
  EXPECT_EQ(r.forceY[0], 4.0);
  EXPECT_TRUE(std::isnan(r.firstSlipTime));
}

TEST(FrictionHistory, PeakConfirmedByTheHoldWhenMuNeverFalls) {
  FrictionMeasurement m = rule();
  m.peakHold = 0.5;
  m.kinetic = false;
  const double dt = 0.01;
  FrictionHistory h(m, 1.0, dt);
  int s = 0;
  // A plateau at mu = 0.8 from t = 1: the hold confirms it at t = 1.5 and the run is then known.
  for (; s <= 1000 && !h.known(); ++s) {
    const double t = s * dt;
    h.observe(t, std::min(t, 1.0) * 0.8, 0.0, true, true);
  }
  EXPECT_TRUE(h.known());
  EXPECT_NEAR((s - 1) * dt, 1.5, 1e-9);
  EXPECT_DOUBLE_EQ(h.summary().muStatic, 0.8);
  EXPECT_TRUE(std::isnan(h.summary().muKinetic));  // not asked for
}

TEST(FrictionHistory, KineticWindowIncompleteIsNaNAndNotKnown) {
  const double dt = 0.01;
  FrictionHistory h(rule(), 1.0, dt);
  for (int s = 0; s <= 300; ++s) h.observe(s * dt, triangle(s * dt), 0.0, true, true);  // ends at t = 3 < 3.5
  EXPECT_TRUE(h.peakConfirmed());
  EXPECT_FALSE(h.known());
  EXPECT_FALSE(h.summary().kineticComplete);
  EXPECT_TRUE(std::isnan(h.summary().muKinetic));
}

TEST(FrictionHistory, AnEarlierLowerPeakDoesNotEnterTheWindow) {
  // mu rises to 0.6, falls to 0.3 before every site slipped, then rises to the true peak 1 at
  // t = 3 and stays at 0.4 after t = 4: the window follows the true peak.
  auto mu = [](double t) {
    if (t <= 1) return 0.6 * t;
    if (t <= 2) return 0.6 - 0.3 * (t - 1);
    if (t <= 3) return 0.3 + 0.7 * (t - 2);
    if (t <= 4) return 1.0 - 0.6 * (t - 3);
    return 0.4;
  };
  const double dt = 0.01;
  FrictionHistory h(rule(), 1.0, dt);
  for (int s = 0; s <= 700; ++s) {
    const double t = s * dt;
    h.observe(t, mu(t), 0.0, true, t >= 2.5);
  }
  const FrictionSummary r = h.summary();
  EXPECT_DOUBLE_EQ(r.muStatic, 1.0);
  EXPECT_NEAR(r.peakTime, 3.0, 1e-9);
  EXPECT_NEAR(r.muKinetic, 0.4, 1e-12);  // window [4.5, 5.5]
}

TEST(FrictionHistory, HistorySampledAtTheInterval) {
  FrictionMeasurement m = rule();
  m.historyInterval = 0.1;
  const double dt = 0.01;
  FrictionHistory h(m, 1.0, dt);
  for (int s = 0; s < 100; ++s) h.observe(s * dt, 0.1, 0.0, false, false);
  const FrictionSummary r = h.summary();
  ASSERT_EQ(r.time.size(), 10u);
  for (std::size_t k = 0; k < r.time.size(); ++k) EXPECT_NEAR(r.time[k], 0.1 * k, 1e-9);
}

namespace {

// The steady rule: the FEM's defaults in units of a loading time of 1.
FrictionMeasurement steadyRule(double latestDelay) {
  FrictionMeasurement m = rule();
  m.kineticDelay = 0.5;
  m.kineticWidth = 1.0;
  m.kineticSteadyTolerance = 0.002;
  m.kineticLatestDelay = latestDelay;
  return m;
}

// Peak 1 at t = 1, collapse to 0.3 at t = 1.2, reload to the plateau 0.5 at t = 3.
double collapseAndReload(double t) {
  if (t <= 1) return t;
  if (t <= 1.2) return 1.0 - 3.5 * (t - 1);
  if (t <= 3) return 0.3 + 0.2 * (t - 1.2) / 1.8;
  return 0.5;
}

// Runs h until it knows everything (or t_end); returns the last time observed.
template <class Mu>
double runUntilKnown(FrictionHistory& h, Mu mu, double dt, double tEnd) {
  double t = 0;
  for (int s = 0; t < tEnd && !h.known(); ++s) {
    t = s * dt;
    h.observe(t, mu(t), 0.0, true, true);
  }
  return t;
}

}  // namespace

TEST(FrictionHistory, SteadyWindowSlidesPastTheReload) {
  const double dt = 0.001;
  FrictionHistory fixed(rule(), 1.0, dt), steady(steadyRule(4.0), 1.0, dt);
  runUntilKnown(fixed, collapseAndReload, dt, 10.0);
  const double end = runUntilKnown(steady, collapseAndReload, dt, 10.0);
  const FrictionSummary f = fixed.summary(), s = steady.summary();
  // The fixed window [2.5, 3.5] holds the end of the reload: below the plateau, not tested.
  EXPECT_LT(f.muKinetic, 0.499);
  EXPECT_FALSE(f.kineticSteadyTested);
  // The steady window starts once the quarters agree, on the plateau, and the run stops there.
  EXPECT_TRUE(s.kineticComplete);
  EXPECT_TRUE(s.kineticSteadyTested);
  EXPECT_TRUE(s.kineticSteady);
  EXPECT_LE(s.kineticSpread, 0.002);
  EXPECT_NEAR(s.muKinetic, 0.5, 0.5 * 0.002);
  EXPECT_GT(s.kineticFrom, 2.5);
  EXPECT_LT(s.kineticFrom, 3.0);
  EXPECT_NEAR(s.kineticTo - s.kineticFrom, 1.0, 1e-12);
  EXPECT_NEAR(end, s.kineticTo, 1.5 * dt);
}

TEST(FrictionHistory, WindowNotSteadyByTheLatestStartIsReportedSo) {
  // After the peak mu wanders with a period of 4 t_load: no window of 1 t_load is steady.
  auto wander = [](double t) { return t <= 1 ? t : 0.5 + 0.1 * std::sin(2 * M_PI * (t - 1) / 4.0); };
  const double dt = 0.001;
  FrictionHistory h(steadyRule(2.0), 1.0, dt);
  const double end = runUntilKnown(h, wander, dt, 20.0);
  const FrictionSummary s = h.summary();
  EXPECT_TRUE(h.known());
  EXPECT_TRUE(s.kineticComplete);
  EXPECT_TRUE(s.kineticSteadyTested);
  EXPECT_FALSE(s.kineticSteady);
  EXPECT_GT(s.kineticSpread, 0.002);
  EXPECT_NEAR(s.kineticFrom, 3.0, 1e-9);  // the latest start, 2 after the peak at t = 1
  EXPECT_NEAR(end, 4.0, 1.5 * dt);        // the run stops at its end, not later
}

TEST(FrictionHistory, StationaryOscillationIsSteadyAtOnce) {
  // Stick-slip much faster than the window averages out in each quarter: steady at the first window.
  auto ringing = [](double t) { return t <= 1 ? t : 0.5 + 0.05 * std::sin(2 * M_PI * (t - 1) / 0.01); };
  const double dt = 0.0001;
  FrictionHistory h(steadyRule(4.0), 1.0, dt);
  runUntilKnown(h, ringing, dt, 20.0);
  const FrictionSummary s = h.summary();
  EXPECT_TRUE(s.kineticSteady);
  EXPECT_NEAR(s.kineticFrom, 1.5, 1e-9);
  EXPECT_NEAR(s.muKinetic, 0.5, 1e-3);
}

TEST(FrictionHistory, ZeroToleranceKeepsTheFixedWindow) {
  FrictionMeasurement m = steadyRule(4.0);
  m.kineticSteadyTolerance = 0.0;
  const double dt = 0.001;
  FrictionHistory h(m, 1.0, dt);
  runUntilKnown(h, collapseAndReload, dt, 10.0);
  const FrictionSummary s = h.summary();
  EXPECT_NEAR(s.kineticFrom, 1.5, 1e-9);  // the peak at 1 + delay 0.5, whatever the steadiness
  EXPECT_FALSE(s.kineticSteadyTested);
  EXPECT_FALSE(s.kineticSteady);
  EXPECT_GT(s.kineticSpread, 0.002);  // reported, not acted on
}
