// What the FEM prints beside mu_k (kinetic_error_estimate.hpp): the mu_k study's ladder judged as a
// statistical one (window means with the standard error of their batch-mean range), never a bar,
// and for the non-graded plate the offsets from the exact steady value (the state law at the
// sliding speed, written out here as Eq. 1).
#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/fem/kinetic_error_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A mu_k study of three rungs of the non-graded plate refined in every direction at the defaults.
std::string kineticTable(double coarse, double medium, double fine, double spread) {
  char text[400];
  std::snprintf(text, sizeof text,
                "# law d_c property delta nx nz edge_ratio edge_band element dt_safety contact mu_k spread\n"
                "state 2.5e-8 none 0 50 5 1 0 q1 0.6 penalty %.6f %g\n"
                "state 2.5e-8 none 0 100 10 1 0 q1 0.6 penalty %.6f %g\n"
                "state 2.5e-8 none 0 200 20 1 0 q1 0.6 penalty %.6f %g\n",
                coarse, spread, medium, spread, fine, spread);
  return text;
}

Grading frictionGraded(double delta) {
  Grading g;
  g.profile = GradingProfile::Linear;
  g.property = GradedProperty::Friction;
  g.delta = delta;
  return g;
}

}  // namespace

TEST(FemKineticError, TheDefaultMeshLadderShowsNoMeshSignalAboveItsWindowsSpread) {
  const FemParameters q;  // 100 x 100 x 10, the state law, the paper's plate
  const std::string basis = kineticErrorBasis(q, Grading{}, 0.6);
  EXPECT_TRUE(contains(basis, "mu_k ladder 50x50x5/100x100x10/200x200x20")) << basis;
  EXPECT_TRUE(contains(basis, "no mesh signal")) << basis;
  // Eq. 1 at the sliding speed is the state law's steady state: the exact mu_k of steady sliding.
  const double exact = q.plate.muKinetic + (q.plate.muStatic - q.plate.muKinetic) *
                                               std::exp(-q.plate.velocity / q.frictionLaw.criticalVelocity);
  char value[32];
  std::snprintf(value, sizeof value, "exact steady value %.6f", exact);
  EXPECT_TRUE(contains(basis, value)) << basis;
  EXPECT_EQ(discretisationError(q, Grading{}, 0.6).kineticBasis, basis) << "the run prints the study's verdict";
}

TEST(FemKineticError, TheWindowsStandardErrorIsTheRangeOverTheExpectedRangeOfFourSamples) {
  EXPECT_NEAR(windowStandardError(0.6, 0.002), 0.6 * 0.002 / (2.059 * 2.0), 1e-15);
  EXPECT_NEAR(windowStandardError(-0.6, 0.002), windowStandardError(0.6, 0.002), 1e-15);
}

TEST(FemKineticError, DifferencesWithinTheWindowsHalfWidthsAreNoSignal) {
  // 95 % half-width of a difference of two rungs: t(3) sqrt(2) se = 3.182 x 1.414 x 2.9e-4 = 1.3e-3.
  const std::string basis = kineticErrorBasis(FemParameters{}, Grading{}, 0.6, kineticTable(0.6007, 0.6010, 0.6006, 0.002));
  EXPECT_TRUE(contains(basis, "no mesh signal")) << basis;
}

TEST(FemKineticError, AConvergingLadderStillPrintsNoBarWithoutTheTimeStepAndContactStudies) {
  const std::string basis =
      kineticErrorBasis(FemParameters{}, Grading{}, 0.6, kineticTable(0.630, 0.615, 0.6075, 1e-5));
  EXPECT_TRUE(contains(basis, "the mesh ladder converges")) << basis;
  EXPECT_TRUE(contains(basis, "not studied for mu_k")) << basis;
  const std::string grows = kineticErrorBasis(FemParameters{}, Grading{}, 0.6, kineticTable(0.630, 0.625, 0.615, 1e-5));
  EXPECT_TRUE(contains(grows, "not converged")) << grows;
}

TEST(FemKineticError, PlatesMeshesAndStepsOutsideTheStudyAreSaidToBe) {
  const std::string table = kineticTable(0.6007, 0.6010, 0.6006, 0.002);
  const std::string noLadder = "no mu_k ladder of this plate and mesh";
  EXPECT_TRUE(contains(kineticErrorBasis(FemParameters{}, frictionGraded(0.2), 0.6, table), noLadder));
  EXPECT_TRUE(contains(kineticErrorBasis(FemParameters{}, Grading{}, 0.3, table), noLadder)) << "another time step";
  FemParameters paperMesh;
  paperMesh.nz = 5;
  EXPECT_TRUE(contains(kineticErrorBasis(paperMesh, Grading{}, 0.6, table), noLadder));
  FemParameters finest;  // the ladder's finest member is found as well
  finest.nx = finest.ny = 200;
  finest.nz = 20;
  EXPECT_TRUE(contains(kineticErrorBasis(finest, Grading{}, 0.6, table), "no mesh signal"));
}

TEST(FemKineticError, ARowWithoutItsSpreadIsAnErrorNamingTheTable) {
  const std::string table = "state 2.5e-8 none 0 50 5 1 0 q1 0.6 penalty 0.600732\n";
  try {
    kineticErrorBasis(FemParameters{}, Grading{}, 0.6, table);
    FAIL() << "a row without its spread was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "fem_study_kinetic.tsv")) << e.what();
    EXPECT_TRUE(contains(e.what(), "line 1")) << e.what();
  }
}

TEST(FemKineticError, OfTwoLaddersHoldingTheRunTheFinestIsJudged) {
  // 100x100x10 lies in 50/100/200 (not converged) and in 100/200/400 (converging): the finer ladder,
  // the likelier to be asymptotic, is the one read, as for mu_s. The coarser alone would say
  // "not converged".
  const std::string table = kineticTable(0.630, 0.625, 0.615, 1e-5) +
                            "state 2.5e-8 none 0 400 40 1 0 q1 0.6 penalty 0.611000 1e-5\n";
  const std::string basis = kineticErrorBasis(FemParameters{}, Grading{}, 0.6, table);
  EXPECT_TRUE(contains(basis, "mu_k ladder 100x100x10/200x200x20/400x400x40: 0.625000, 0.615000, 0.611000")) << basis;
  EXPECT_TRUE(contains(basis, "the mesh ladder converges")) << basis;
  const std::string coarserOnly = kineticErrorBasis(FemParameters{}, Grading{}, 0.6, kineticTable(0.630, 0.625, 0.615, 1e-5));
  EXPECT_TRUE(contains(coarserOnly, "not converged")) << coarserOnly;
}
