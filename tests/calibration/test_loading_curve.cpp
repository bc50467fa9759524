// The loading slope and peak a calibration compares (calibration/loading_curve.hpp), and the
// sticking slope G v / (p l_z) of the spring-block model against a real realisation.
#include "gradfric/calibration/loading_curve.hpp"
#include "gradfric/calibration/spring_block_evaluation.hpp"
#include "gradfric/sbm/model.hpp"

#include "gradfric/campaign/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::calibration;

namespace {

// mu rises as 2 t to 1 at t = 0.5, then falls; sampled every 0.01.
void ramp(std::vector<double>* t, std::vector<double>* mu, double wiggle = 0.0) {
  for (int i = 0; i <= 100; ++i) {
    const double x = 0.01 * i;
    t->push_back(x);
    mu->push_back((x <= 0.5 ? 2 * x : 1.0 - (x - 0.5)) + wiggle * std::sin(40 * x));
  }
}

}  // namespace

TEST(LoadingCurve, SlopeOfALineOverTheWindowAndItsPeak) {
  std::vector<double> t, mu;
  ramp(&t, &mu);
  const LoadingFeatures f = loadingFeatures(t, mu, LoadingWindow{});
  EXPECT_DOUBLE_EQ(f.peak, 1.0);
  EXPECT_DOUBLE_EQ(f.peakTime, 0.5);
  EXPECT_NEAR(f.slope, 2.0, 1e-12);
  EXPECT_EQ(f.samples, 21);  // mu = 0.2 .. 0.6 at t = 0.10 .. 0.30, before the peak only
  EXPECT_NEAR(f.slopeStdError, 0.0, 1e-9);
}

TEST(LoadingCurve, AGivenPeakSetsTheWindowAndNoiseGivesAnError) {
  std::vector<double> t, mu;
  ramp(&t, &mu, 0.01);
  const LoadingFeatures own = loadingFeatures(t, mu, LoadingWindow{0.2, 0.6}, 0.5, 0.25);
  EXPECT_DOUBLE_EQ(own.peak, 0.5);  // the model's own measurement is kept
  EXPECT_LE(own.samples, 11);       // 0.1 <= mu <= 0.3
  EXPECT_NEAR(own.slope, 2.0, 0.2);
  EXPECT_GT(own.slopeStdError, 0.0);
  // The 95 % half-width of the fit: Student t with samples - 2 degrees of freedom, wider than 1.96 SE.
  EXPECT_NEAR(own.slopeHalfWidth, gradfric::campaign::studentTQuantile(0.975, own.samples - 2) * own.slopeStdError, 1e-12);
  EXPECT_GT(own.slopeHalfWidth, 2.2 * own.slopeStdError);
}

TEST(LoadingCurve, InterpolatesInsideAndIsNaNOutside) {
  const std::vector<double> t{1, 2, 4}, mu{0, 1, 3};
  const auto v = interpolate(t, mu, {0.5, 1, 1.5, 3, 4, 5});
  EXPECT_TRUE(std::isnan(v[0]));
  EXPECT_DOUBLE_EQ(v[1], 0);
  EXPECT_DOUBLE_EQ(v[2], 0.5);
  EXPECT_DOUBLE_EQ(v[3], 2);
  EXPECT_DOUBLE_EQ(v[4], 3);
  EXPECT_TRUE(std::isnan(v[5]));
}

// The first guess of a calibration: while every block sticks, mu(t) rises at G v / (p l_z); a
// realisation of the model (20 x 20 blocks, sigma 3 %) has that slope over 0.2-0.6 mu_s.
TEST(LoadingCurve, SpringBlockSlopeIsTheSliderSprings) {
  SpringBlockScene scene;
  scene.base.blocksPerSide = 20;
  scene.base.layerThickness = 4e-5;
  scene.base.surface.sigmaStatic = scene.base.surface.sigmaKinetic = 0.03;
  scene.base.damping = 0.1 * std::sqrt(scene.base.axialStiffness(scene.base.plate.youngsModulus) / scene.base.blockMass());
  scene.base.timeStep = sbm::defaultTimeStep(scene.base, scene.grading);
  sbm::Request request;
  const double load = scene.base.loadingTime();
  request.measurement.historyInterval = 1e-3 * load;
  request.measurement.peakHold = 0.25 * load;
  request.maxTime = 20 * load;
  const sbm::Result r = sbm::simulate(scene.base, scene.grading, request, StreamKey{1, 0, 0});
  const LoadingFeatures f =
      loadingFeatures(r.friction.time, r.friction.mu, LoadingWindow{}, r.friction.muStatic, r.friction.peakTime);
  ASSERT_GT(f.samples, 100);
  EXPECT_NEAR(f.slope / stickingSlope(scene, 4e-5), 1.0, 1e-6);
  EXPECT_NEAR(layerThicknessForSlope(scene, f.slope), 4e-5, 4e-11);
}
