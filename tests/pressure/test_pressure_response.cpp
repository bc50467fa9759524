// The load-dependent pressure of the spring-block model (physics/pressure_response.hpp,
// sbm/pressure_coupling.hpp): a zero shape is the uniform model bit for bit; the moment-balance
// shape has zero mean and first moment H at any angle and under a static pressure field; a run
// with it keeps the total normal force p L^2 and the moment balance H F at every step, and starts
// slipping at the trailing edge. Under -pressure_response_select grading each run takes the g of
// its grading (or is refused naming the option), zero shapes stay the uniform model bit for bit,
// and each g keeps the total normal force.
#include "../sbm/sbm_support.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/lattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

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

// -pressure_response_select grading: a g per grading, selected by each run's grading and angle.
namespace {

// A map on a 21 x 21 node grid (pixel centres on the nodes, as gradfric-fem writes it) of the
// edge-concentrated tilt g = amplitude ((2x/L - 1)^9 + shift); shift 0 and amplitude 0: zero.
std::shared_ptr<const FieldMap> tiltMap(double amplitude, double shift, const std::string& name) {
  const double L = Plate{}.length, h = L / 20;
  auto map = std::make_shared<FieldMap>();
  map->nx = map->ny = 21;
  map->x0 = map->y0 = -0.5 * h;
  map->x1 = map->y1 = L + 0.5 * h;
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 21; ++i) map->values.push_back(amplitude * (std::pow(2.0 * i / 20 - 1.0, 9) + shift));
  map->source = name;
  return map;
}

ResponseGrading keyOf(GradedProperty property, double delta) {
  return responseGradingOf(Grading{GradingProfile::Linear, property, delta, 10}, 0.0);
}

// Non-graded, E +0.2 and E -0.2, each its own map.
PressureResponse perGrading(double scale) {
  PressureResponse r;
  r.source = PressureResponseSource::Fem;
  r.perGrading = true;
  r.measured = {{tiltMap(0.8 * scale, 0.0, "none.h5"), responseGradingOf(Grading{}, 0.0), "none.h5"},
                {tiltMap(0.6 * scale, 0.01 * scale, "E+0.2.h5"), keyOf(GradedProperty::YoungsModulus, 0.2), "E+0.2.h5"},
                {tiltMap(1.0 * scale, -0.01 * scale, "E-0.2.h5"), keyOf(GradedProperty::YoungsModulus, -0.2), "E-0.2.h5"}};
  return r;
}

const std::vector<Grading> kSweep = {Grading{}, Grading{GradingProfile::Linear, GradedProperty::YoungsModulus, 0.2, 10},
                                     Grading{GradingProfile::Linear, GradedProperty::YoungsModulus, -0.2, 10}};

}  // namespace

TEST(PressureResponsePerGrading, EachRunTakesTheGOfItsGrading) {
  const PressureResponse r = perGrading(1.0);
  for (std::size_t k = 0; k < kSweep.size(); ++k) {
    const PressureResponse one = selectedFor(r, kSweep[k], 0.0, "point");
    EXPECT_FALSE(one.perGrading);
    EXPECT_EQ(one.map, r.measured[k].map) << k;
  }
  // Every non-graded plate has the non-graded g: Delta = 0 under any profile and property.
  EXPECT_EQ(selectedFor(r, Grading{GradingProfile::Linear, GradedProperty::Friction, 0.0, 10}, 0.0).map,
            r.measured[0].map);
  // One g for every run without the selection.
  PressureResponse same = r;
  same.perGrading = false;
  same.map = r.measured[1].map;
  EXPECT_EQ(selectedFor(same, kSweep[2], 0.0).map, r.measured[1].map);
  // None for another property, Delta, band count or angle: the option, its value, the run and
  // the gradings the files hold.
  const Grading friction{GradingProfile::Linear, GradedProperty::Friction, 0.2, 10};
  const Grading wider{GradingProfile::Linear, GradedProperty::YoungsModulus, 0.4, 10};
  const Grading fewerBands{GradingProfile::Linear, GradedProperty::YoungsModulus, 0.2, 5};
  for (const auto& [grading, theta] : {std::pair{friction, 0.0}, std::pair{wider, 0.0}, std::pair{fewerBands, 0.0},
                                       std::pair{kSweep[1], 90.0}, std::pair{Grading{}, 90.0}}) {
    try {
      (void)selectedFor(r, grading, theta, "sweep point 7");
      ADD_FAILURE() << describe(grading) << " at theta " << theta << " was given a g";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(e.option(), "-pressure_response_file");
      EXPECT_NE(m.find("-pressure_response_file = none.h5,E+0.2.h5,E-0.2.h5"), std::string::npos) << m;
      EXPECT_NE(m.find("sweep point 7 (" + responseGradingOf(grading, theta).describe() + ") has none"),
                std::string::npos) << m;
      EXPECT_NE(m.find("E linear Delta = -0.2, 10 bands, theta = 0 (E-0.2.h5)"), std::string::npos) << m;
    }
  }
}

TEST(PressureResponsePerGrading, ZeroShapesAreTheUniformModelBitForBit) {
  const PressureResponse zeros = perGrading(0.0);
  for (const Grading& g : kSweep) {
    const Parameters uniform = sbm::testing::paperParameters(16, 0.028, g);
    Parameters coupled = uniform;
    coupled.pressureResponse = zeros;
    const Result a = run(uniform, g), b = run(coupled, g);
    EXPECT_TRUE(b.pressureCoupling.active);
    EXPECT_EQ(a.friction.muStatic, b.friction.muStatic) << describe(g);
    EXPECT_EQ(a.friction.peakTime, b.friction.peakTime);
    EXPECT_EQ(a.steps, b.steps);
    ASSERT_EQ(a.friction.mu.size(), b.friction.mu.size());
    for (std::size_t i = 0; i < a.friction.mu.size(); ++i) ASSERT_EQ(a.friction.mu[i], b.friction.mu[i]) << i;
  }
}

TEST(PressureResponsePerGrading, EveryShapeKeepsTheNormalForceAndIsTheOneSelected) {
  const PressureResponse r = perGrading(1.0);
  std::vector<double> peaks;
  for (std::size_t k = 0; k < kSweep.size(); ++k) {
    const Grading& g = kSweep[k];
    Parameters p = sbm::testing::paperParameters(16, 0.028, g);
    p.pressureResponse = r;
    const Result coupled = run(p, g);
    const PressureCouplingRecord& c = coupled.pressureCoupling;
    ASSERT_TRUE(c.active);
    EXPECT_GT(c.updates, coupled.steps / 2);
    EXPECT_LT(c.largestForceError, 1e-13) << describe(g);  // sum F_n,i = p L^2 with this point's g
    EXPECT_LT(c.smallestFactor, 1.0);
    // The same run as with that one file for every point: the selection hands the run its g.
    Parameters one = p;
    one.pressureResponse.perGrading = false;
    one.pressureResponse.map = r.measured[k].map;
    const Result alone = run(one, g);
    EXPECT_EQ(coupled.friction.muStatic, alone.friction.muStatic) << describe(g);
    EXPECT_EQ(coupled.steps, alone.steps);
    peaks.push_back(coupled.friction.muStatic);
  }
  // The three g differ, and so do the runs with them (the test can see a wrong selection).
  Parameters p = sbm::testing::paperParameters(16, 0.028, kSweep[1]);
  p.pressureResponse = perGrading(1.0);
  p.pressureResponse.perGrading = false;
  p.pressureResponse.map = p.pressureResponse.measured[2].map;  // E -0.2's g on the E +0.2 plate
  EXPECT_NE(run(p, kSweep[1]).friction.muStatic, peaks[1]);
}
