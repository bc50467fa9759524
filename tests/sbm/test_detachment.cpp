// The detachment time (physics/observables.hpp, FrictionSummary::detachmentTime) in real
// spring-block runs: checked against the first-slip map the model stores block by block, and
// against the peak rule that waits for it.
#include "sbm_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace gradfric;
using namespace gradfric::sbm;
using gradfric::sbm::testing::defaultRequest;
using gradfric::sbm::testing::paperParameters;
using gradfric::sbm::testing::triangular;

namespace {

Grading linearFriction(double delta) {
  return sbm::testing::grading(GradingProfile::Linear, GradedProperty::Friction, delta);
}

// The latest first slip of the map; NaN if some block never slipped.
double latestFirstSlip(const Result& r) {
  double latest = -INFINITY;
  for (double t : r.firstSlipTime) {
    if (std::isnan(t)) return NAN;
    latest = std::max(latest, t);
  }
  return latest;
}

}  // namespace

TEST(Detachment, IsTheLatestFirstSlipOfTheMap) {
  // The map stores each block's first slip at the time of the step it started in, the observer
  // the time of the first step after which every block had: the same step, so the same double.
  struct Case {
    std::string name;
    Grading grading;
    double sigma;
  };
  const Case cases[] = {{"linear friction Delta 0.3, sigma 5 %", linearFriction(0.3), 0.05},
                        {"triangular E Delta -0.4", triangular(GradedProperty::YoungsModulus, -0.4), 0.0},
                        {"uniform, sigma 0", {}, 0.0}};
  for (const Case& c : cases)
    for (Integrator integrator : {Integrator::VelocityVerlet, Integrator::RK4})
      for (Kernel kernel : {Kernel::Fast, Kernel::Reference}) {
        Parameters p = paperParameters(20, c.sigma, c.grading);
        p.integrator = integrator;
        p.timeStep = defaultTimeStep(p, c.grading);
        const std::string where = c.name + (integrator == Integrator::RK4 ? ", RK4" : ", Verlet") +
                                  (kernel == Kernel::Fast ? ", fast kernel" : ", reference kernel");
        const Request q = defaultRequest(p);
        ASSERT_TRUE(q.measurement.firstSlipMap);
        const Result r = simulate(p, c.grading, q, {7, 0, 1}, kernel);
        ASSERT_EQ(r.firstSlipTime.size(), std::size_t(20 * 20)) << where;
        ASSERT_TRUE(r.friction.peakConfirmed) << where;
        const double latest = latestFirstSlip(r);
        ASSERT_TRUE(std::isfinite(latest)) << where << ": a block never slipped";
        EXPECT_EQ(r.friction.detachmentTime, latest) << where;
        EXPECT_EQ(r.friction.firstSlipTime, *std::min_element(r.firstSlipTime.begin(), r.firstSlipTime.end()))
            << where;
      }
}

TEST(Detachment, LiesBetweenTheFirstSlipAndThePeaksConfirmation) {
  // A run asked for mu_s alone stops at the observation that confirmed the peak, t_c = end - dt.
  // The rule confirms only once every block slipped, so t_detach <= t_c; and it confirms at the
  // first step at which every block has slipped and the peak held for -friction_peak_hold, so
  // t_c < max(t_detach, t_peak + hold) + dt. Nothing orders t_detach and t_peak.
  struct Case {
    std::string name;
    Grading grading;
    double sigma;
  };
  const Case cases[] = {{"uniform plate without disorder", {}, 0.0},
                        {"linear friction Delta 0.3", linearFriction(0.3), 0.0},
                        {"linear friction Delta -0.3, sigma 5 %", linearFriction(-0.3), 0.05}};
  for (const Case& c : cases) {
    const Parameters p = paperParameters(30, c.sigma, c.grading);
    Request q = defaultRequest(p);
    q.measurement.kinetic = false;
    const Result r = simulate(p, c.grading, q, {11, 0, 0});
    const FrictionSummary& f = r.friction;
    const double dt = p.timeStep, confirmed = r.endTime - dt;
    ASSERT_TRUE(f.peakConfirmed) << c.name;
    ASSERT_TRUE(std::isfinite(f.detachmentTime)) << c.name;
    std::printf("%-40s first slip %.6e s, detachment %.6e s, peak %.6e s, confirmed %.6e s\n", c.name.c_str(),
                f.firstSlipTime, f.detachmentTime, f.peakTime, confirmed);
    EXPECT_LE(f.firstSlipTime, f.detachmentTime) << c.name;
    EXPECT_LE(f.detachmentTime, confirmed + 1e-9 * dt) << c.name;
    EXPECT_LT(confirmed, std::max(f.detachmentTime, f.peakTime + q.measurement.peakHold) + dt * (1 + 1e-9)) << c.name;
  }
}
