// The friction memory of Eq. 1 in the FEM contact (physics/slip_state_law.hpp,
// -friction_law exponential -fem_slip_length; docs/studies/fem-steady-sliding.md):
// * with constant friction (mu_s = mu_k) the slip state cannot change anything: the whole run is
//   the run without it, bit for bit;
// * at the default (healing only: Eq. 1's weakening at once) mu_s and mu(t) up to the peak are
//   Eq. 1's without state, bit for bit;
// * on the reduced plate (10 x 10 x 5, non-graded, Eq. 1 with mu_s 1, mu_k 0.6, v = 10 v_c) at the
//   default slip length, once the plate slides steadily, the global mu is Eq. 1's local value at v
//   (0.60002) within 1 %, with either contact; without a slip length it stays far above it
//   (node-scale stick-slip: a stopped node is back at mu_s).
// Node by node (without a slip length the contact forces are the plain law's bit for bit, with
// both contact methods), without PETSc: tests/unit/test_fem_contact_laws.cpp.
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

// The friction memory belongs to the stateless laws: these runs take Eq. 1 itself (the state law,
// the default, has its own tests: test_fem_state_law.cpp).
FemParameters memoryCoarse(int nx, int ny, int nz) {
  FemParameters q = test::coarse(nx, ny, nz);
  q.frictionLaw.name = "exponential";
  return q;
}

// Mean of mu over the recorded steps with time in [from, to].
double meanMu(const FemRunResult& r, double from, double to, double* lowest, double* highest) {
  double sum = 0, count = 0;
  *lowest = 1e300;
  *highest = -1e300;
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    if (r.time[i] < from || r.time[i] > to) continue;
    sum += r.mu[i];
    count += 1;
    *lowest = std::min(*lowest, r.mu[i]);
    *highest = std::max(*highest, r.mu[i]);
  }
  return count > 0 ? sum / count : std::nan("");
}

FemRunResult run(const FemParameters& q) {
  PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
  return runPlateExperiment(model);
}

}  // namespace

TEST(FemSlipState, WithConstantFrictionTheSlipStateChangesNothing) {
  FemParameters q = memoryCoarse(10, 10, 5);
  q.contactMethod = ContactMethod::Kinematic;
  q.plate.muStatic = q.plate.muKinetic = 1.0;
  FemParameters withState = q, without = q;
  withState.slipLength = 1e-8;
  without.slipLength = 0.0;
  const FemRunResult a = run(withState), b = run(without);
  ASSERT_EQ(a.mu.size(), b.mu.size());
  for (std::size_t i = 0; i < a.mu.size(); ++i) ASSERT_EQ(a.mu[i], b.mu[i]) << "step " << i;
  EXPECT_EQ(a.friction.muStatic, b.friction.muStatic);
}

TEST(FemSlipState, TheDefaultSlipLengthLeavesMuStaticBitForBit) {
  FemParameters q = memoryCoarse(10, 10, 5);
  FemParameters without = q;
  without.slipLength = 0.0;
  ASSERT_TRUE(q.slipHealingOnly && q.slipLength > 0.0) << "the default: healing only, over a slip length";
  const FemRunResult a = run(q), b = run(without);
  EXPECT_EQ(a.friction.muStatic, b.friction.muStatic);
  EXPECT_EQ(a.friction.peakTime, b.friction.peakTime);
  std::size_t same = 0;
  for (std::size_t i = 0; i < std::min(a.mu.size(), b.mu.size()) && a.time[i] <= a.friction.peakTime; ++i) {
    ASSERT_EQ(a.mu[i], b.mu[i]) << "step " << i << " before the peak";
    ++same;
  }
  PetscPrintf(PETSC_COMM_WORLD, "mu_s %.6f with and without the slip length (%zu identical steps to the peak)\n",
              a.friction.muStatic, same);
  EXPECT_GT(same, 1000u);
}

TEST(FemSlipState, NonGradedMuKineticIsEquationOneAtTheSliderSpeed) {
  for (ContactMethod method : {ContactMethod::Kinematic, ContactMethod::Penalty}) {
    FemParameters q = memoryCoarse(10, 10, 5);  // the default slip length
    q.contactMethod = method;
    q.stopWhenKnown = false;
    const double ts = q.eq2PeakTime();
    q.slideTime = 5.0 * ts;
    const double eq1 = q.plate.muKinetic + (q.plate.muStatic - q.plate.muKinetic) * std::exp(-q.plate.velocity / q.frictionLaw.criticalVelocity);
    ASSERT_GT(q.slipLength, 0.0) << "a slip length is on by default";
    const FemRunResult r = run(q);
    ASSERT_TRUE(r.friction.peakConfirmed);
    // Steady sliding: the last 1.5 t_s (the peak is at about 0.9 t_s, confirmed by 2 t_s).
    double lo = 0, hi = 0;
    const double steady = meanMu(r, 3.5 * ts, 5.0 * ts, &lo, &hi);
    PetscPrintf(PETSC_COMM_WORLD,
                "%s, D_c %.3g m: mu_s %.6f, mu_k (window) %.6f, steady mu over 3.5-5 t_s %.6f (range %.6f-%.6f), "
                "Eq. 1 at v %.6f (%+.3f %%)\n",
                contactMethodName(method), q.slipLength, r.friction.muStatic, r.friction.muKinetic, steady, lo, hi,
                eq1, 100 * (steady / eq1 - 1));
    EXPECT_NEAR(steady / eq1, 1.0, 0.01) << contactMethodName(method);
    EXPECT_LT(hi - lo, 0.02) << "steady: no node-scale stick-slip";
    if (method == ContactMethod::Kinematic) {  // the control: without the slip length, stick-slip far above
      q.slipLength = 0.0;
      const FemRunResult off = run(q);
      const double without = meanMu(off, 3.5 * ts, 5.0 * ts, &lo, &hi);
      PetscPrintf(PETSC_COMM_WORLD, "  without slip length: steady-window mu %.6f (range %.6f-%.6f)\n", without, lo,
                  hi);
      EXPECT_GT(without, 1.1 * eq1);
    }
  }
}
