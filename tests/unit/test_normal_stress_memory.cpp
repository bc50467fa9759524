// The friction law's normal-stress memory (physics/normal_stress_memory.hpp) and the contact that
// uses it (fem/contact_penalty.hpp, fem/contact_kinematic.hpp), against closed forms:
// * p* follows a pressure step as p + (p0 - p) exp(-(|V| + V*) t / L), whatever the time step;
// * while sliding fast (V >> V*) it moves 1 - 1/e of the way over a slip L: a slip length;
// * a sliding penalty node after a pressure jump feels mu p*, not mu p;
// * off, the contact is bit for bit the contact without a memory;
// * its length is the law's, in units of D_c; its per-site state is pending until commit.
#include "gradfric/fem/contact_kinematic.hpp"
#include "gradfric/fem/contact_penalty.hpp"
#include "gradfric/fem/contact_law.hpp"
#include "gradfric/physics/normal_stress_memory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

constexpr double kLength = 1e-7, kSpeed = 1e-3;  // L [m], V* [m/s]

CoulombStickSlip constantFriction(double mu) {
  return CoulombStickSlip::make({SiteLayout::Uniform, 1, {mu}, {mu}}, FrictionLawSettings{"coulomb", 1e-4, 1e-8});
}

// A memory of length L [m] and reference speed V* [m/s], as the law builds it (L in units of D_c).
NormalStressMemory memoryOf(double length, double speed) {
  FrictionLawSettings settings{"state", 1e-4, 2.5e-8};
  settings.memoryLength = length / settings.slipLength;
  settings.memorySpeed = speed;
  return NormalStressMemory::make(settings, 1);
}

}  // namespace

TEST(NormalStressMemory, FollowsAPressureStepExactlyWhateverTheStep) {
  const NormalStressMemory filter = memoryOf(kLength, kSpeed);
  const double p0 = 1e4, p1 = 1.5e4, rate = 0.05, duration = 4e-6;
  const double expected = p1 + (p0 - p1) * std::exp(-(rate + kSpeed) * duration / kLength);
  for (int steps : {1, 7, 1000}) {
    double filtered = p0;
    for (int i = 0; i < steps; ++i) filtered = filter.relax(filtered, p1, rate, duration / steps);
    EXPECT_NEAR(filtered, expected, 1e-12 * p1) << steps << " steps";
  }
  // The slip rate enters by its magnitude: sliding backwards filters the same.
  EXPECT_DOUBLE_EQ(filter.relax(p0, p1, -rate, duration), filter.relax(p0, p1, rate, duration));
}

TEST(NormalStressMemory, IsASlipLengthWhenSlidingFast) {
  const NormalStressMemory filter = memoryOf(kLength, 0.0);
  const double p0 = 1e4, p1 = 2e4;
  for (double rate : {0.01, 0.1, 1.0}) {  // slide L at each rate: the same fraction of the way
    const double filtered = filter.relax(p0, p1, rate, kLength / rate);
    EXPECT_NEAR((filtered - p0) / (p1 - p0), 1.0 - std::exp(-1.0), 1e-12) << rate;
  }
  // At rest with V* it follows over L / V*; without V* it keeps its value.
  EXPECT_NEAR((filter.relax(p0, p1, 0.0, 1.0) - p0), 0.0, 0.0);
  const NormalStressMemory withSpeed = memoryOf(kLength, kSpeed);
  EXPECT_NEAR((withSpeed.relax(p0, p1, 0.0, kLength / kSpeed) - p0) / (p1 - p0), 1.0 - std::exp(-1.0), 1e-12);
}

TEST(NormalStressMemory, OffIsThePressureItself) {
  const NormalStressMemory off;
  EXPECT_FALSE(off.active());
  EXPECT_EQ(off.relax(3.0, 7.0, 0.2, 1e-6), 7.0);
}

TEST(NormalStressMemory, SlidingPenaltyNodeFeelsTheFilteredPressure) {
  const double mu = 1.2, kn = 1e13, kt = 1e13, dt = 1e-8, rate = 0.1;
  CoulombStickSlip law = constantFriction(mu);
  const NormalStressMemory filter = memoryOf(kLength, kSpeed);
  const PenaltyStiffness k{kn, kt};
  const double p0 = 1e4, p1 = 1.3e4;
  const double gap = -p1 / kn;  // the pressure has jumped from p0 to p1
  double filtered = p0, ux = 0.0, anchor = -mu * p0 / kt;  // sliding: its elastic slip at the cap
  for (int step = 1; step <= 50; ++step) {
    ux += rate * dt;  // sliding at `rate`: far beyond the elastic slip, always at the cap
    const ContactTraction r =
        penaltyContact(k, law, 0, gap, ux, 0.0, anchor, 0.0, rate, 0.0, true, rate * dt, dt, filter, filtered);
    ASSERT_EQ(r.state, ContactState::Slip);
    const double slid = rate * dt * step;
    const double expected = p1 + (p0 - p1) * std::exp(-(rate + kSpeed) * slid / (rate * kLength));
    EXPECT_NEAR(r.frictionPressure, expected, 1e-9 * p1);
    EXPECT_NEAR(std::fabs(r.tx), mu * expected, 1e-9 * mu * p1);  // mu p*, below mu p
    EXPECT_LT(std::fabs(r.tx), mu * p1);
    EXPECT_DOUBLE_EQ(r.pressure, p1);
    filtered = r.frictionPressure;
    anchor = r.anchorX;
  }
}

TEST(NormalStressMemory, OffLeavesTheContactBitForBit) {
  CoulombStickSlip law = constantFriction(0.8);
  const PenaltyStiffness k{1e13, 5e12};
  for (bool slipping : {false, true}) {
    const ContactTraction plain = penaltyContact(k, law, 0, -1e-9, 3e-9, -1e-9, 0.0, 0.0, 0.02, 0.01, slipping, 2e-10, 1e-8);
    const ContactTraction off = penaltyContact(k, law, 0, -1e-9, 3e-9, -1e-9, 0.0, 0.0, 0.02, 0.01, slipping, 2e-10,
                                               1e-8, NormalStressMemory{}, 12345.0);
    EXPECT_EQ(plain.tx, off.tx);
    EXPECT_EQ(plain.ty, off.ty);
    EXPECT_EQ(plain.pressure, off.pressure);
    EXPECT_EQ(off.frictionPressure, off.pressure);
  }
  const double v[3] = {0.01, 0.0, -0.001}, a[3] = {5e3, 0.0, -2e4};
  const KinematicContactForce plain = kinematicContact(law, 0, 1e-9, 1e-8, 0.0, v, a);
  const KinematicContactForce off = kinematicContact(law, 0, 1e-9, 1e-8, 0.0, v, a, 0.0, NormalStressMemory{}, 99.0);
  EXPECT_EQ(plain.fx, off.fx);
  EXPECT_EQ(plain.fn, off.fn);
  EXPECT_EQ(off.frictionForce, off.fn);
}

TEST(NormalStressMemory, KinematicNodeFeelsTheFilteredNormalForce) {
  CoulombStickSlip law = constantFriction(1.0);
  const NormalStressMemory filter = memoryOf(kLength, kSpeed);
  const double mass = 1e-9, dt = 1e-8, slip = 1e-9;
  const double v[3] = {0.1, 0.0, -0.01}, a[3] = {0.0, 0.0, -1e5};  // sliding fast, pressed onto the plane
  const KinematicContactForce plain = kinematicContact(law, 0, mass, dt, 0.0, v, a, slip);
  const double lagging = 0.5 * plain.fn;
  const KinematicContactForce r = kinematicContact(law, 0, mass, dt, 0.0, v, a, slip, filter, lagging);
  const double expected = filter.relax(lagging, plain.fn, slip / dt, dt);
  EXPECT_DOUBLE_EQ(r.frictionForce, expected);
  EXPECT_EQ(r.state, ContactState::Slip);
  EXPECT_NEAR(std::hypot(r.fx, r.fy), expected, 1e-12 * plain.fn);
  EXPECT_EQ(r.fn, plain.fn);
}

TEST(NormalStressMemory, IsTheLawsInUnitsOfDcWithAStatePerSite) {
  FrictionLawSettings settings{"state", 1e-4, 5e-8};
  EXPECT_FALSE(NormalStressMemory::make(settings, 3).active());  // none by default
  settings.memoryLength = 4;
  NormalStressMemory memory = NormalStressMemory::make(settings, 3);
  EXPECT_DOUBLE_EQ(memory.length, 2e-7);  // 4 D_c
  EXPECT_DOUBLE_EQ(memory.speed, FrictionLawSettings::kMemorySpeed);
  EXPECT_DOUBLE_EQ(memory.relaxationTime(0.09), 2e-7 / 0.1);
  memory.settle(1, 7e3);
  EXPECT_EQ(memory.rememberedAt(1, 0.0), 7e3);
  // An evaluation is pending: a second one in the same step starts from the committed value.
  memory.setPending(1, memory.relax(memory.rememberedAt(1, 0.0), 9e3, 0.1, 1e-7));
  EXPECT_EQ(memory.rememberedAt(1, 0.0), 7e3);
  const double after = memory.pending[1];
  memory.commit();
  EXPECT_EQ(memory.rememberedAt(1, 0.0), after);
  EXPECT_NEAR((after - 7e3) / 2e3, 1.0 - std::exp(-(0.1 + 0.01) * 1e-7 / 2e-7), 1e-12);  // (|V| + V*) dt / L
  // Its state travels with the strength law's through a checkpoint.
  StateArchive saved;
  memory.archive(saved);
  NormalStressMemory restored = NormalStressMemory::make(settings, 3);
  StateArchive reading(saved.bytes());
  restored.archive(reading);
  EXPECT_EQ(restored.remembered, memory.remembered);
}

TEST(NormalStressMemory, TheContactLawCommitsBothStates) {
  FrictionLawSettings settings{"state", 1e-4, 2.5e-8};
  settings.memoryLength = 2;
  FrictionSites sites{SiteLayout::PerSite, 2, {1.2, 0.8}, {0.6, 0.6}};
  ContactLaw law = makeContactLaw(settings, sites, 2, 0.0, false);
  ASSERT_TRUE(law.normalStress.active());
  law.normalStress.setPending(0, 5.0);
  law.visitStrength([](auto& strength) {
    if constexpr (std::is_same_v<std::decay_t<decltype(strength)>, StateWeakening>) strength.advance(0, 1e-8, 1e-7);
  });
  law.commit();
  EXPECT_EQ(law.normalStress.rememberedAt(0, 0.0), 5.0);
  double theta = -1;
  law.visitStrength([&](auto& strength) {
    if constexpr (std::is_same_v<std::decay_t<decltype(strength)>, StateWeakening>) theta = strength.state[0];
  });
  EXPECT_GT(theta, 0.0);
}
