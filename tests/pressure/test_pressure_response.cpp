// The load-dependent pressure of the spring-block model (physics/pressure_response.hpp,
// sbm/pressure_coupling.hpp): a zero shape is the uniform model bit for bit; the moment-balance
// shape has zero mean and first moment H at any angle and under a static pressure field; a run
// with it keeps the total normal force p L^2 and the moment balance H F at every step, and starts
// slipping at the trailing edge.
#include "../sbm/sbm_support.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/lattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

Result run(const Parameters& p, const Grading& g, Kernel kernel = Kernel::Fast) {
  const Request q = sbm::testing::defaultRequest(p);
  return simulate(p, g, q, StreamKey{11, 0, 3}, kernel);
}

PressureResponse zeroMap() {
  auto map = std::make_shared<FieldMap>();
  map->nx = map->ny = 4;
  map->x0 = map->y0 = 0.0;
  map->x1 = map->y1 = Plate{}.length;
  map->values.assign(16, 0.0);
  map->source = "zeros";
  PressureResponse r;
  r.source = PressureResponseSource::Fem;
  r.map = map;
  return r;
}

PressureResponse moment(double edgeLength) {
  PressureResponse r;
  r.source = PressureResponseSource::MomentBalance;
  r.edgeLength = edgeLength;
  return r;
}

double largestMagnitude(const std::vector<double>& g) {
  double m = 0.0;
  for (double v : g) m = std::max(m, std::fabs(v));
  return m;
}

}  // namespace

TEST(PressureResponse, ZeroShapeIsTheUniformModelBitForBit) {
  for (const Grading& g : {Grading{}, Grading{GradingProfile::Linear, GradedProperty::Friction, 0.2, 10}}) {
    for (double sigma : {0.0, 0.028}) {
      const Parameters uniform = sbm::testing::paperParameters(16, sigma, g);
      Parameters coupled = uniform;
      coupled.pressureResponse = zeroMap();
      const Result a = run(uniform, g), b = run(coupled, g);
      EXPECT_TRUE(b.pressureCoupling.active);
      EXPECT_GT(b.pressureCoupling.updates, 0);
      EXPECT_EQ(a.friction.muStatic, b.friction.muStatic);
      EXPECT_EQ(a.friction.muKinetic, b.friction.muKinetic);
      EXPECT_EQ(a.friction.peakTime, b.friction.peakTime);
      EXPECT_EQ(a.steps, b.steps);
      ASSERT_EQ(a.friction.mu.size(), b.friction.mu.size());
      for (std::size_t i = 0; i < a.friction.mu.size(); ++i) ASSERT_EQ(a.friction.mu[i], b.friction.mu[i]) << i;
      ASSERT_EQ(a.firstSlipTime.size(), b.firstSlipTime.size());
      for (std::size_t i = 0; i < a.firstSlipTime.size(); ++i) {
        if (!(std::isnan(a.firstSlipTime[i]) && std::isnan(b.firstSlipTime[i]))) {
          ASSERT_EQ(a.firstSlipTime[i], b.firstSlipTime[i]);
        }
      }
    }
  }
}

TEST(PressureResponse, MomentBalanceShapeHasZeroMeanAndMomentH) {
  const Plate plate;
  const int nb = 24;
  const double l = plate.length / nb;
  for (double angle : {0.0, 90.0, 180.0, 30.0, -135.0}) {
    const std::vector<double> s = slidingCoordinates(nb, plate.length, angle);
    const std::vector<double> g = pressureResponseShape(moment(plate.thickness), nb, plate.length, plate.thickness, angle);
    const ShapeMoments m = shapeMoments(g, s);
    EXPECT_NEAR(m.mean, 0.0, 1e-14 * largestMagnitude(g)) << angle;
    EXPECT_NEAR(m.moment / plate.thickness, 1.0, 1e-12) << angle;
  }
  // Along x: the leading edge (x = L) overloads, the trailing one unloads, antisymmetrically, and
  // the concentration decays by exp(-l / lambda) per column from the edge.
  const double lambda = 0.7 * plate.thickness;
  const std::vector<double> g = pressureResponseShape(moment(lambda), nb, plate.length, plate.thickness, 0.0);
  EXPECT_GT(g[nb - 1], 0.0);
  EXPECT_LT(g[0], 0.0);
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) EXPECT_NEAR(g[r * nb + c], -g[r * nb + nb - 1 - c], 1e-12 * g[nb - 1]);
  const double ratio = (g[nb - 2] - g[nb / 2]) / (g[nb - 1] - g[nb / 2]);
  EXPECT_NEAR(ratio, std::exp(-l / lambda), 0.01);
  // A sharper edge concentrates more: the edge value grows as lambda falls.
  const std::vector<double> sharp = pressureResponseShape(moment(0.3 * plate.thickness), nb, plate.length,
                                                          plate.thickness, 0.0);
  EXPECT_GT(sharp[nb - 1], g[nb - 1]);
}

TEST(PressureResponse, WeightedShapeKeepsTheTotalAndMomentUnderAStaticPressureField) {
  const Plate plate;
  const int nb = 20;
  std::vector<double> w(nb * nb);
  double sum = 0.0;
  for (int i = 0; i < nb * nb; ++i) sum += (w[i] = 1.0 + 0.3 * std::sin(0.37 * i));
  for (double& v : w) v *= nb * nb / sum;  // mean 1, as a normalised pressure field
  const std::vector<double> s = slidingCoordinates(nb, plate.length, 20.0);
  const std::vector<double> g =
      pressureResponseShape(moment(plate.thickness), nb, plate.length, plate.thickness, 20.0, w);
  const ShapeMoments m = shapeMoments(g, s, w);
  EXPECT_NEAR(m.mean, 0.0, 1e-14 * largestMagnitude(g));
  EXPECT_NEAR(m.moment / plate.thickness, 1.0, 1e-12);
}

TEST(PressureResponse, RunKeepsNormalForceAndMomentBalanceAtEveryStep) {
  const Grading g{GradingProfile::Linear, GradedProperty::Friction, 0.2, 10};
  Parameters p = sbm::testing::paperParameters(16, 0.028, g);
  p.pressureResponse = moment(p.plate.thickness);
  for (Kernel kernel : {Kernel::Fast, Kernel::Reference}) {
    const Result r = run(p, g, kernel);
    const PressureCouplingRecord& c = r.pressureCoupling;
    ASSERT_TRUE(c.active);
    EXPECT_GT(c.updates, r.steps / 2);  // mu(t) changes nearly every step
    EXPECT_LT(c.largestForceError, 1e-13);   // sum F_n,i = p L^2 to round-off
    EXPECT_LT(c.largestMomentError, 1e-12);  // sum s_i dF_n,i = H F to round-off (units of mu)
    EXPECT_EQ(c.clampedSites, 0);
    EXPECT_LT(c.smallestFactor, 1.0);
    EXPECT_GT(c.smallestFactor, 0.0);
    // The trailing edge (column 0) is unloaded: it slips first.
    double earliest = INFINITY;
    int column = -1;
    for (int i = 0; i < 16 * 16; ++i)
      if (r.firstSlipTime[i] < earliest) earliest = r.firstSlipTime[i], column = i % 16;
    EXPECT_EQ(column, 0);
  }
}

TEST(PressureResponse, UnloadedTrailingEdgeLowersTheStaticPeak) {
  // Without dispersion the uniform plate's blocks all hold to mu_s; the tilted pressure lets the
  // trailing edge go early and the front runs through the plate before the mean reaches mu_s.
  Parameters p = sbm::testing::paperParameters(16, 0.0);
  const double uniform = run(p, {}).friction.muStatic;
  p.pressureResponse = moment(p.plate.thickness);
  const double coupled = run(p, {}).friction.muStatic;
  EXPECT_LT(coupled, uniform - 0.01);
  EXPECT_GT(coupled, 0.5 * uniform);
}

TEST(PressureResponse, QuietPhaseJumpStaysExactUnderTheRisingLoad) {
  // The jump over the quiet phase is built on bounded strengths and ends at or before the first
  // slip: the same run, bit for bit, as stepping every block from t = 0; and it does jump.
  for (double sigma : {0.0, 0.028}) {
    const Grading g{GradingProfile::Linear, GradedProperty::YoungsModulus, -0.2, 10};
    Parameters jump = sbm::testing::paperParameters(20, sigma, g);
    jump.pressureResponse = moment(0.5 * jump.plate.thickness);
    Parameters stepped = jump;
    stepped.skipIdle = false;
    const Result a = run(jump, g), b = run(stepped, g);
    EXPECT_EQ(a.friction.muStatic, b.friction.muStatic);
    EXPECT_EQ(a.friction.muKinetic, b.friction.muKinetic);
    EXPECT_EQ(a.steps, b.steps);
    ASSERT_EQ(a.friction.mu.size(), b.friction.mu.size());
    for (std::size_t i = 0; i < a.friction.mu.size(); ++i) ASSERT_EQ(a.friction.mu[i], b.friction.mu[i]) << i;
    for (std::size_t i = 0; i < a.firstSlipTime.size(); ++i) ASSERT_EQ(a.firstSlipTime[i], b.firstSlipTime[i]) << i;
    // The first slip comes well into the loading: there was a quiet phase to jump over.
    EXPECT_GT(a.friction.firstSlipTime, 0.2 * jump.loadingTime());
  }
}
