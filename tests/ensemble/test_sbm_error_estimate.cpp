// The spring-block discretisation bar (include/gradfric/ensemble/sbm_error_estimate.hpp): the ladder
// rule on made-up ladders whose answers are known (monotone, oscillating, not converged, within the
// statistical error), the settings outside the study, and the embedded table's rows.
#include "gradfric/ensemble/sbm_error_estimate.hpp"

#include "gradfric/campaign/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace gradfric;
using namespace gradfric::ensemble;
using namespace gradfric::campaign;

namespace {

SbmStudyRow lattice(const std::string& grading, double delta, int blocks, const std::string& observable, double mean,
                    double stdError, int realisations = 100) {
  SbmStudyRow r;
  r.kind = "lattice";
  r.law = "coulomb";
  r.grading = grading;
  r.delta = delta;
  r.blocks = blocks;
  r.observable = observable;
  r.realisations = realisations;
  r.value = mean;
  r.stdError = stdError;
  return r;
}

// A study: the ladder 60/120/240/480 of mu_s at Delta = 0 with the given means, and a dt row.
std::vector<SbmStudyRow> study(double m60, double m120, double m240, double m480, double se = 1e-6) {
  std::vector<SbmStudyRow> rows = {lattice("none", 0, 60, "mu_s", m60, se), lattice("none", 0, 120, "mu_s", m120, se),
                                   lattice("none", 0, 240, "mu_s", m240, se), lattice("none", 0, 480, "mu_s", m480, se)};
  SbmStudyRow dt = lattice("friction", 0.2, 120, "mu_s", 8e-4, 0, 3);
  dt.kind = "dt";
  dt.dt = 3e-8;
  rows.push_back(dt);
  return rows;
}

struct Setting {
  sbm::Parameters parameters;
  Grading grading;
  FrictionMeasurement measurement;
};

// The default scene's plate at N_b blocks, as the options resolve it.
Setting setting(int blocks) {
  Setting s;
  sbm::Parameters& p = s.parameters;
  p.blocksPerSide = blocks;
  p.damping = 0.1 * std::sqrt(p.axialStiffness(p.plate.youngsModulus) / p.blockMass());
  p.timeStep = defaultTimeStep(p, s.grading);
  const double load = p.loadingTime();
  s.measurement.peakHold = 0.25 * load;
  s.measurement.kineticDelay = 0.5 * load;
  s.measurement.kineticWidth = load;
  return s;
}

SbmDiscretisation barOf(const Setting& s, const std::vector<SbmStudyRow>& rows, bool kinetic = false) {
  return sbmDiscretisationError(s.parameters, s.grading, s.measurement, kinetic, rows);
}

}  // namespace

TEST(SbmErrorEstimate, MonotoneLadderGivesTheGciOfTheFinestLadder) {
  // mu = 0.9 + 0.6 / N_b: first order, limit 0.9. N_b = 120 is the coarsest member of 120/240/480.
  auto mu = [](int n) { return 0.9 + 0.6 / n; };
  const auto rows = study(mu(60), mu(120), mu(240), mu(480));
  const SbmDiscretisation bar = barOf(setting(120), rows);
  ASSERT_TRUE(bar.measured) << bar.basis;
  // mu(120) - mu_ext = mu(120) + mu(240) - 2 mu(480) at p = 1: its half-width t sqrt(6) se.
  const double h = t95(99) * 1e-6 * std::sqrt(6.0);
  EXPECT_NEAR(bar.lattice.relative, 1.25 * (mu(120) - 0.9 + h) / 0.9, 1e-9);
  EXPECT_NE(bar.lattice.basis.find("120/240/480"), std::string::npos) << bar.lattice.basis;
  EXPECT_NE(bar.lattice.basis.find("observed order 1.00"), std::string::npos) << bar.lattice.basis;
  EXPECT_NEAR(bar.timeStep.relative, 1.25 * 8e-4 * std::max(1.0, setting(120).parameters.timeStep / 3e-8), 1e-12);
  EXPECT_DOUBLE_EQ(bar.relative, bar.lattice.relative + bar.timeStep.relative);
  // A higher observed order is capped at 2 (the extrapolation then moves less than it would).
  auto fast = [](int n) { return 0.9 + 600.0 / (double(n) * n * n); };
  const SbmDiscretisation capped = barOf(setting(240), study(fast(60), fast(120), fast(240), fast(480)));
  ASSERT_TRUE(capped.lattice.measured);
  const double extrapolated = fast(480) + (fast(480) - fast(240)) / 3.0;
  const double hCapped = t95(99) * 1e-6 * std::sqrt(2.0) * 4.0 / 3.0;  // c = (0, 4/3, -4/3)
  EXPECT_NEAR(capped.lattice.relative, 1.25 * (fast(240) - extrapolated + hCapped) / extrapolated, 1e-9);
  // The statistical error widens the bound: 1.25 x the 95 % half-width of mu(120) - mu_ext.
  const SbmDiscretisation noisy = barOf(setting(120), study(mu(60), mu(120), mu(240), mu(480), 1e-5));
  EXPECT_NEAR(noisy.lattice.relative - bar.lattice.relative, 1.25 * 9 * h / 0.9, 1e-9);
}

TEST(SbmErrorEstimate, OscillatingLadderIsBoundedByItsLastTwoMeans) {
  const auto rows = study(0.95, 0.90, 0.93, 0.915);
  const SbmDiscretisation bar = barOf(setting(480), rows);  // finest member of 120/240/480
  ASSERT_TRUE(bar.lattice.measured) << bar.lattice.basis;
  EXPECT_NE(bar.lattice.basis.find("oscillating"), std::string::npos);
  const double h = t95(99) * 1e-6 * std::sqrt(2.0);
  EXPECT_NEAR(bar.lattice.relative, 1.25 * (0.015 + h) / 0.915, 1e-9);
}

TEST(SbmErrorEstimate, NoBarWhereTheLadderDoesNotConverge) {
  // Differences -1.0 % then -0.9 %: observed order 0.15.
  const SbmDiscretisation slow = barOf(setting(120), study(0.95, 0.94, 0.9306, 0.9222));
  EXPECT_FALSE(slow.measured);
  EXPECT_FALSE(slow.lattice.measured);
  EXPECT_NE(slow.basis.find("not converged"), std::string::npos) << slow.basis;
  EXPECT_EQ(describeBar(slow).rfind("discretisation error not measured: ", 0), 0u);
  // Converged on the point values (order 0.74) but not across their statistical error.
  const SbmDiscretisation blurred = barOf(setting(120), study(0.95, 0.94, 0.93, 0.924, 4e-4));
  EXPECT_FALSE(blurred.lattice.measured);
  EXPECT_NE(blurred.basis.find("across the statistical error"), std::string::npos) << blurred.basis;
  // A second difference within its own statistical error proves nothing.
  const SbmDiscretisation flat = barOf(setting(120), study(0.95, 0.94, 0.93, 0.9299, 1e-4));
  EXPECT_FALSE(flat.lattice.measured);
  EXPECT_NE(flat.basis.find("proves nothing"), std::string::npos) << flat.basis;
}

TEST(SbmErrorEstimate, AFinerLadderThatDoesNotConvergeTakesTheBarAway) {
  // 60/120/240 converges (differences -2.0 %, -0.5 %: order 2), 120/240/480 does not (-0.5 %,
  // -0.5 %): N_b = 60 gets no bar, although its own ladder converges.
  const auto rows = study(1.0, 0.98, 0.9751, 0.9702);
  const SbmDiscretisation coarse = barOf(setting(60), rows);
  EXPECT_FALSE(coarse.lattice.measured) << coarse.lattice.basis;
  EXPECT_NE(coarse.lattice.basis.find("120/240/480"), std::string::npos) << coarse.lattice.basis;
  EXPECT_NE(coarse.lattice.basis.find("no bar for N_b = 60"), std::string::npos) << coarse.lattice.basis;
  // Where the finer ladder only lacks a signal (its second difference within the statistical
  // error), it disproves nothing: 60/120/240 (-2.1 %, -0.5 %) bounds N_b = 60.
  const SbmDiscretisation flat = barOf(setting(60), study(0.97, 0.95, 0.945, 0.9449, 1e-4));
  EXPECT_TRUE(flat.lattice.measured) << flat.lattice.basis;
}

TEST(SbmErrorEstimate, OutsideTheStudyNothingIsClaimed) {
  auto mu = [](int n) { return 0.9 + 0.6 / n; };
  const auto rows = study(mu(60), mu(120), mu(240), mu(480));
  auto reason = [&](const Setting& s, bool kinetic = false) {
    const SbmDiscretisation bar = barOf(s, rows, kinetic);
    EXPECT_FALSE(bar.measured);
    return bar.basis;
  };
  EXPECT_NE(reason(setting(100)).find("N_b = 100 not in a lattice ladder"), std::string::npos);
  Setting sigma = setting(120);
  sigma.parameters.sigmaStatic = 0.05;
  EXPECT_NE(reason(sigma).find("sigma"), std::string::npos);
  Setting dense = setting(120);
  dense.parameters.plate.density = 2400;
  EXPECT_NE(reason(dense).find("plate other than the paper's (rho [kg/m^3] 2400, the paper's 1200)"), std::string::npos)
      << reason(dense);
  Setting thick = setting(120);  // H does not enter the spring-block model: the bar stands
  thick.parameters.plate.thickness = 1e-4;
  EXPECT_TRUE(barOf(thick, rows, false).measured) << barOf(thick, rows, false).basis;
  Setting rk4 = setting(120);
  rk4.parameters.integrator = sbm::Integrator::RK4;
  EXPECT_NE(reason(rk4).find("integrator"), std::string::npos);
  Setting coarseStep = setting(120);
  coarseStep.parameters.timeStep = 1e-7;
  EXPECT_NE(reason(coarseStep).find("above the studied default step"), std::string::npos);
  Setting graded = setting(120);  // the study holds no graded ladder here
  graded.grading.profile = GradingProfile::Linear;
  graded.grading.property = GradedProperty::Friction;
  graded.grading.delta = 0.3;
  EXPECT_NE(reason(graded).find("no lattice ladder of mu_s for law coulomb and this grading (the study's: none Delta = 0)"),
            std::string::npos) << reason(graded);
  graded.grading.property = GradedProperty::YoungsModulus;
  EXPECT_NE(reason(graded).find("grading other than a linear friction grading"), std::string::npos);
  Setting law = setting(120);
  law.parameters.frictionLaw.name = "exponential";
  EXPECT_NE(reason(law).find("no lattice ladder"), std::string::npos);
  EXPECT_NE(reason(setting(120), true).find("no lattice ladder of mu_k"), std::string::npos);
  Setting window = setting(120);
  window.measurement.kineticWidth *= 2;
  EXPECT_NE(reason(window, true).find("mu_k window"), std::string::npos);
  // A smaller step than the default is covered (the error grows with dt): same lattice term.
  Setting fine = setting(120);
  fine.parameters.timeStep = 1e-8;
  const SbmDiscretisation finer = barOf(fine, rows);
  ASSERT_TRUE(finer.measured);
  EXPECT_DOUBLE_EQ(finer.timeStep.relative, 1.25 * 8e-4);
}

TEST(SbmErrorEstimate, TheEmbeddedStudyHoldsBothLaddersAndTheStep) {
  const auto& rows = sbmStudy();
  for (const char* observable : {"mu_s", "mu_k"})
    for (const auto& [grading, delta] : {std::pair{"none", 0.0}, std::pair{"friction", 0.2}})
      for (int n : {60, 120, 240, 480}) {
        int found = 0;
        for (const auto& r : rows)
          if (r.kind == "lattice" && r.grading == grading && r.delta == delta && r.blocks == n && r.observable == observable) {
            ++found;
            EXPECT_GT(r.realisations, 1);
            EXPECT_GT(r.stdError, 0.0);
            EXPECT_GT(r.value, 0.3);
          }
        EXPECT_EQ(found, 1) << observable << " " << grading << " " << n;
      }
  int steps = 0;
  for (const auto& r : rows) steps += r.kind == "dt" && r.dt > 0 && r.value > 0;
  EXPECT_EQ(steps, 2);  // mu_s and mu_k at the default step
  // The default scene's plate is inside the study: its bar is a number or a ladder's verdict.
  const SbmDiscretisation bar = barOf(setting(120), rows);
  EXPECT_TRUE(bar.timeStep.measured) << bar.basis;
  EXPECT_NE(bar.basis.find("lattice N_b 120/240/480"), std::string::npos) << bar.basis;
}

TEST(SbmErrorEstimate, AStudyRowThatDoesNotReadIsAnErrorNotADroppedRung) {
  const std::string header = "# kind law grading delta N_b observable R value std_error dt\n";
  const std::vector<SbmStudyRow> rows =
      parseSbmStudy(header + "lattice\tcoulomb\tnone\t0\t60\tmu_s\t100\t0.91\t1e-3\tdefault\n"
                             "dt\tcoulomb\tfriction\t0.2\t120\tmu_s\t3\t8e-4\t0\t3e-8\n");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].dt, 0.0);
  EXPECT_EQ(rows[1].dt, 3e-8);
  for (const std::string bad : {"lattice\tcoulomb\tnone\t0\t60\tmu_s\t100\t0.91\t1e-3\n",
                                "dt\tcoulomb\tfriction\t0.2\t120\tmu_s\t3\t8e-4\t0\t3e-8s\n",
                                "lattice\tcoulomb\tnone\t0\t60\tmu_s\tmany\t0.91\t1e-3\tdefault\n"}) {
    try {
      parseSbmStudy(header + bad);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("docs/sbm_study.tsv), line 2"), std::string::npos) << e.what();
    }
  }
}
