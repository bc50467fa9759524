// The state law (physics/state_weakening_law.hpp, the FEM's default) in the FEM plate: on the
// reduced plate (10 x 10 x 5, non-graded), once the plate slides steadily at v = 10 v_c, the
// global mu is Eq. 1's value at v (the law's steady state) within 1 %, with either contact; with
// constant friction it slides on a plateau at its peak. A contact node pulled at a constant fast
// speed (it weakens over D_c of slip, in closed form), without PETSc: tests/unit/test_fem_contact_laws.cpp.
#include "gradfric/fem/simulation.hpp"
#include "fem_test_util.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

TEST(FemStateLaw, NonGradedSteadySlidingIsEquationOneAtTheSliderSpeed) {
  for (ContactMethod method : {ContactMethod::Kinematic, ContactMethod::Penalty}) {
    FemParameters q = test::coarse(10, 10, 5);
    ASSERT_EQ(q.frictionLaw.name, "state") << "the default law";
    q.contactMethod = method;
    q.stopWhenKnown = false;
    const double ts = q.eq2PeakTime();
    q.slideTime = 5.0 * ts;
    const double eq1 = q.plate.muKinetic + (q.plate.muStatic - q.plate.muKinetic) *
                                               std::exp(-q.plate.velocity / q.frictionLaw.criticalVelocity);
    PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    const FemRunResult r = runPlateExperiment(model);
    ASSERT_TRUE(r.friction.peakConfirmed);
    double sum = 0, lo = 1e300, hi = -1e300;
    int count = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i)
      if (r.time[i] >= 3.5 * ts) {
        sum += r.mu[i];
        lo = std::min(lo, r.mu[i]);
        hi = std::max(hi, r.mu[i]);
        ++count;
      }
    ASSERT_GT(count, 100);
    const double steady = sum / count;
    PetscPrintf(PETSC_COMM_WORLD,
                "%s: mu_s %.6f, steady mu over 3.5-5 t_s %.6f (range %.6f-%.6f), Eq. 1 at v %.6f (%+.3f %%)\n",
                contactMethodName(method), r.friction.muStatic, steady, lo, hi, eq1, 100 * (steady / eq1 - 1));
    EXPECT_NEAR(steady / eq1, 1.0, 0.01) << contactMethodName(method);
    EXPECT_GT(r.friction.muStatic, 1.2 * eq1) << "a static peak above the kinetic level";
  }
}

TEST(FemStateLaw, ConstantFrictionSlidesOnAPlateauAtItsPeak) {
  // mu_s = mu_k: no weakening, so no static peak above the sliding level (the flutter threshold of
  // a solid sliding on a rigid plane is mu = 1: 0.6 is below it, 1 on it).
  for (double mu : {0.6, 1.0}) {
    Plate plate;
    plate.muStatic = plate.muKinetic = mu;
    FemParameters q = test::coarse(10, 10, 5, plate);
    q.stopWhenKnown = false;
    const double ts = q.eq2PeakTime();
    q.slideTime = 5.0 * ts;
    PlateModel model(PETSC_COMM_WORLD, q, test::noGrading());
    const FemRunResult r = runPlateExperiment(model);
    double sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i)
      if (r.time[i] >= 3.5 * ts) sum += r.mu[i], ++count;
    ASSERT_GT(count, 100);
    const double plateau = sum / count;
    PetscPrintf(PETSC_COMM_WORLD, "constant mu %.1f: peak %.6f, plateau over 3.5-5 t_s %.6f (%+.3f %%)\n", mu,
                r.friction.muStatic, plateau, 100 * (plateau / r.friction.muStatic - 1));
    EXPECT_NEAR(plateau / r.friction.muStatic, 1.0, 0.01) << "mu " << mu;
    EXPECT_NEAR(plateau, mu, 0.01 * mu);
  }
}
