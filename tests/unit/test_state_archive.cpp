// The state archive of checkpoints (core/state_archive.hpp): a saved object restored into a fresh
// one continues bit for bit (the friction observer fed the same steps after a restore gives the
// same summary), and a checkpoint of another shape is refused naming the record.
#include "gradfric/core/state_archive.hpp"
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/state_weakening_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace gradfric;

namespace {

FrictionMeasurement steadyRule() {
  FrictionMeasurement m;
  m.peakDrop = 0.01;
  m.kineticDelay = 0.5;
  m.kineticWidth = 0.4;
  m.kineticSteadyTolerance = 0.01;
  m.kineticLatestDelay = 2.0;
  m.historyInterval = 0.03;
  return m;
}

// mu(t) with a peak at t = 1 and a noisy plateau after it (a deterministic sequence).
void feed(FrictionHistory& h, int from, int to) {
  for (int i = from; i < to; ++i) {
    const double t = 0.01 * (i + 1);
    const double mu = t < 1 ? t : 0.6 + 0.01 * std::sin(37.0 * t) * std::exp(-(t - 1));
    h.observe(t, 2.0 * mu * std::cos(0.3), 2.0 * mu * std::sin(0.3), t > 0.2, t > 0.8);
  }
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(StateArchive, ARestoredObserverContinuesBitForBit) {
  FrictionHistory whole(steadyRule(), 2.0, 0.01);
  feed(whole, 0, 400);

  FrictionHistory first(steadyRule(), 2.0, 0.01);
  feed(first, 0, 123);  // interrupted after the peak, inside the kinetic window's search
  StateArchive saved;
  first.archive(saved);
  FrictionHistory resumed(steadyRule(), 2.0, 0.01);
  StateArchive restoring(saved.bytes());
  resumed.archive(restoring);
  restoring.expectEnd();
  feed(resumed, 123, 400);

  const FrictionSummary a = whole.summary(), b = resumed.summary();
  EXPECT_TRUE(sameBits(a.muStatic, b.muStatic));
  EXPECT_TRUE(sameBits(a.muKinetic, b.muKinetic));
  EXPECT_TRUE(sameBits(a.kineticFrom, b.kineticFrom));
  EXPECT_TRUE(sameBits(a.kineticSpread, b.kineticSpread));
  EXPECT_EQ(a.peakConfirmed, b.peakConfirmed);
  EXPECT_EQ(a.kineticSteady, b.kineticSteady);
  ASSERT_EQ(a.mu.size(), b.mu.size());
  for (std::size_t i = 0; i < a.mu.size(); ++i) ASSERT_TRUE(sameBits(a.mu[i], b.mu[i])) << "sample " << i;
  EXPECT_TRUE(a.kineticComplete);  // the case covers the whole rule
}

TEST(StateArchive, TheLawsPerSiteStateRoundTrips) {
  FrictionLawSettings settings;
  settings.criticalVelocity = 1e-4;
  settings.slipLength = 2.5e-8;
  StateWeakening law = StateWeakening::make(FrictionSites{}, settings, 5);
  for (int i = 0; i < 5; ++i) law.state[i] = 1e-9 * (i + 1) / 3.0;
  StateArchive saved;
  law.archive(saved);
  StateWeakening restored = StateWeakening::make(FrictionSites{}, settings, 5);
  StateArchive restoring(saved.bytes());
  restored.archive(restoring);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(sameBits(law.state[i], restored.state[i]));
  // Another number of sites (another mesh or partition) is a mismatch, not a resize.
  StateWeakening other = StateWeakening::make(FrictionSites{}, settings, 6);
  StateArchive again(saved.bytes());
  try {
    other.archive(again);
    FAIL() << "a law of 6 sites took the state of 5";
  } catch (const CheckpointMismatch& e) {
    EXPECT_NE(std::string(e.what()).find("'law.state' has 40 bytes, this run's 48"), std::string::npos) << e.what();
  }
}

TEST(StateArchive, AnotherRecordOrTrailingStateIsRefused) {
  double x = 1.5, y = 0;
  int n = 3;
  StateArchive saved;
  saved.field("x", x);
  saved.field("n", n);
  StateArchive wrongName(saved.bytes());
  try {
    wrongName.field("y", y);
    FAIL() << "a record of another name was read";
  } catch (const CheckpointMismatch& e) {
    EXPECT_NE(std::string(e.what()).find("holds the state 'x' where this run has 'y'"), std::string::npos) << e.what();
  }
  StateArchive shortRead(saved.bytes());
  shortRead.field("x", y);
  EXPECT_EQ(y, 1.5);
  EXPECT_THROW(shortRead.expectEnd(), CheckpointMismatch);  // "n" left over
  StateArchive truncated(std::vector<char>(saved.bytes().begin(), saved.bytes().begin() + 10));
  EXPECT_THROW(truncated.field("x", y), CheckpointMismatch);
}
