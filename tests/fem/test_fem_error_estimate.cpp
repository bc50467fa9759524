// The error bar of the FEM's mu_s (error_estimate.hpp): the measured terms for the studied
// settings, "not measured" outside them, and the printed form.
#include "gradfric/fem/error_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gradfric;
using namespace gradfric::fem;

namespace {

FemParameters paperDefaults() {
  FemParameters q;
  q.resolveDerived();
  return q;
}

Grading linear(GradedProperty property, double delta) {
  Grading g;
  g.profile = GradingProfile::Linear;
  g.property = property;
  g.delta = delta;
  return g;
}

// The mesh terms of docs/accuracy_fem.md, "Error bar", for the remaining paper-mesh points.
constexpr double kModulusLarge = 0.065, kFrictionLarge = 0.116, kModulusTriangular = 0.058,
                 kFrictionAcross = 0.010;

}  // namespace

TEST(FemErrorBar, PaperMeshAtTheDefaultsIsMeasured) {
  const DiscretisationError e = discretisationError(paperDefaults(), Grading{}, 0.6);
  ASSERT_TRUE(e.measured) << e.basis;
  EXPECT_NEAR(e.mesh.relative, 0.057, 1e-12);
  EXPECT_NEAR(e.timeStep.relative, 0.004, 1e-12);
  EXPECT_NEAR(e.contact.relative, 0.004, 1e-12);
  EXPECT_NEAR(e.relative, 0.065, 1e-12);
  const std::string text = withErrorBar(0.886046, e);
  EXPECT_EQ(text.rfind("0.886046 +- 6.5 % (discretisation: mesh 5.7 %, dt 0.4 %, contact 0.4 %; 100x100x5 q1", 0), 0u)
      << text;
  EXPECT_FALSE(e.kineticMeasured);
  EXPECT_NE(withKineticErrorBar(0.39, e).find("not measured"), std::string::npos);
}

TEST(FemErrorBar, EachTermFollowsItsStudy) {
  FemParameters q = paperDefaults();
  EXPECT_NEAR(discretisationError(q, Grading{}, 0.3).timeStep.relative, 0.001, 1e-12);
  EXPECT_NEAR(discretisationError(q, Grading{}, 0.9).timeStep.relative, 0.010, 1e-12);
  EXPECT_NEAR(discretisationError(q, linear(GradedProperty::Friction, -0.2), 0.6).relative, 0.079, 1e-12);
  q.contactMethod = ContactMethod::Kinematic;
  EXPECT_NEAR(discretisationError(q, Grading{}, 0.6).relative, 0.061, 1e-12);
  q = paperDefaults();
  q.nx = q.ny = 25;
  EXPECT_NEAR(discretisationError(q, Grading{}, 0.6).mesh.relative, 0.031, 1e-12);
  EXPECT_NEAR(discretisationError(q, linear(GradedProperty::YoungsModulus, 0.2), 0.6).mesh.relative, 0.033, 1e-12);
  q.element = ElementType::IncompatibleModes;
  EXPECT_NEAR(discretisationError(q, Grading{}, 0.6).mesh.relative, 0.056, 1e-12);
}

// The graded convergence study (docs/accuracy_fem.md, "Graded convergence"): E and friction grading
// on the paper mesh and on 50x50x5 are measured, each with its own row.
TEST(FemErrorBar, GradedPaperMeshIsMeasured) {
  const FemParameters q = paperDefaults();
  for (double delta : {0.2, -0.2, 0.1}) {
    const DiscretisationError e = discretisationError(q, linear(GradedProperty::YoungsModulus, delta), 0.6);
    ASSERT_TRUE(e.measured) << e.basis;
    EXPECT_NEAR(e.mesh.relative, 0.057, 1e-12);
    EXPECT_NE(e.basis.find("100x100x5 q1, E grading"), std::string::npos) << e.basis;
    EXPECT_NE(withErrorBar(0.75, e).find("0.750000 +- "), std::string::npos);
  }
  const DiscretisationError f = discretisationError(q, linear(GradedProperty::Friction, 0.2), 0.6);
  ASSERT_TRUE(f.measured) << f.basis;
  EXPECT_NEAR(f.mesh.relative, 0.071, 1e-12);
  EXPECT_NE(f.basis.find("100x100x5 q1, friction grading"), std::string::npos) << f.basis;
  FemParameters coarse = q;
  coarse.nx = coarse.ny = 50;
  EXPECT_NEAR(discretisationError(coarse, linear(GradedProperty::YoungsModulus, -0.2), 0.6).mesh.relative, 0.094, 1e-12);
  EXPECT_NEAR(discretisationError(coarse, linear(GradedProperty::Friction, 0.2), 0.6).mesh.relative, 0.088, 1e-12);
  // The coarser mesh's graded bar is larger than the paper mesh's. (Graded and non-graded peaks
  // fall together with the refinement at the current penalty: neither bar bounds the other.)
  EXPECT_GT(discretisationError(coarse, linear(GradedProperty::YoungsModulus, 0.2), 0.6).relative,
            discretisationError(q, linear(GradedProperty::YoungsModulus, 0.2), 0.6).relative);
}

// The remaining paper-mesh points of the graded study: linear |Delta| up to 0.4, triangular E up to
// 0.2, friction up to 0.2 sliding across the grading (90 degrees). Each has its own row, and the
// larger gradings carry at least the bar of the +-0.2 row they extend.
TEST(FemErrorBar, LargerAndOtherGradingsOnThePaperMeshAreMeasured) {
  FemParameters q = paperDefaults();
  auto mesh = [&](const FemParameters& p, const Grading& g, const char* basis) {
    const DiscretisationError e = discretisationError(p, g, 0.6);
    EXPECT_TRUE(e.measured) << e.basis;
    EXPECT_NE(e.mesh.basis.find(basis), std::string::npos) << e.mesh.basis;
    return e.mesh.relative;
  };
  for (double delta : {0.4, -0.4, 0.3}) {
    EXPECT_NEAR(mesh(q, linear(GradedProperty::YoungsModulus, delta), "E grading 0.2 < |Delta| <= 0.4"), kModulusLarge, 1e-12);
    EXPECT_NEAR(mesh(q, linear(GradedProperty::Friction, delta), "friction grading 0.2 < |Delta| <= 0.4"), kFrictionLarge,
                1e-12);
  }
  EXPECT_GE(kModulusLarge, discretisationError(q, linear(GradedProperty::YoungsModulus, 0.2), 0.6).mesh.relative);
  EXPECT_GE(kFrictionLarge, discretisationError(q, linear(GradedProperty::Friction, 0.2), 0.6).mesh.relative);
  Grading triangular = linear(GradedProperty::YoungsModulus, -0.2);
  triangular.profile = GradingProfile::Triangular;
  EXPECT_NEAR(mesh(q, triangular, "triangular E"), kModulusTriangular, 1e-12);
  q.plate.slidingAngle = 90;
  for (double delta : {0.2, -0.2})
    EXPECT_NEAR(mesh(q, linear(GradedProperty::Friction, delta), "friction grading at 90 degrees"), kFrictionAcross, 1e-12);
}

TEST(FemErrorBar, OutsideTheStudiesItIsNotMeasured) {
  auto notMeasured = [](const FemParameters& q, const Grading& g, double dtRatio, const char* why) {
    const DiscretisationError e = discretisationError(q, g, dtRatio);
    EXPECT_FALSE(e.measured) << why;
    EXPECT_NE(e.basis.find(why), std::string::npos) << e.basis;
    const std::string text = withErrorBar(0.9, e);
    EXPECT_NE(text.find("(discretisation error not measured: "), std::string::npos) << text;
    EXPECT_EQ(text.find("+-"), std::string::npos) << text;
  };
  FemParameters q = paperDefaults();
  notMeasured(q, Grading{}, 0.95, "dt above 0.9");
  q.nz = 10;  // the graded study's finest meshes have no finer mesh to measure them against
  notMeasured(q, linear(GradedProperty::YoungsModulus, 0.2), 0.6, "mesh 100x100x10 q1 (graded) not in the mesh study");
  q = paperDefaults();
  notMeasured(q, linear(GradedProperty::Friction, 0.5), 0.6, "grading other than");
  Grading triangular = linear(GradedProperty::Friction, 0.2);  // triangular was studied for E only
  triangular.profile = GradingProfile::Triangular;
  notMeasured(q, triangular, 0.6, "grading other than");
  triangular.property = GradedProperty::YoungsModulus;
  triangular.delta = 0.4;
  notMeasured(q, triangular, 0.6, "grading other than");
  q.plate.slidingAngle = 90;  // across the grading: friction +-0.2 only
  notMeasured(q, linear(GradedProperty::YoungsModulus, 0.2), 0.6, "sliding angle other than 0");
  notMeasured(q, linear(GradedProperty::Friction, 0.4), 0.6, "sliding angle other than 0");
  notMeasured(q, Grading{}, 0.6, "sliding angle other than 0");
  q.plate.slidingAngle = 45;
  notMeasured(q, linear(GradedProperty::Friction, 0.2), 0.6, "sliding angle other than 0");
  q = paperDefaults();
  q.nx = q.ny = 50;  // the larger gradings have rows on the paper mesh only
  notMeasured(q, linear(GradedProperty::YoungsModulus, 0.4), 0.6, "mesh 50x50x5 q1 (graded) not in the mesh study");
  q = paperDefaults();
  q.nx = q.ny = 10;
  notMeasured(q, Grading{}, 0.6, "mesh 10x10x5 q1 not in the mesh study");
  q = paperDefaults();
  q.kt = 10 * q.plate.shearModulus() / q.plate.thickness;
  notMeasured(q, Grading{}, 0.6, "penalty stiffness other than 250 G/H");
  q = paperDefaults();
  q.plate.length *= 2;
  q.resolveDerived();
  notMeasured(q, Grading{}, 0.6, "plate or friction law other than the paper's");
  q = paperDefaults();
  q.stiffnessDamping = 3e-8;
  notMeasured(q, Grading{}, 0.6, "damping while sliding");
  q = paperDefaults();
  q.rampTime *= 0.5;
  notMeasured(q, Grading{}, 0.6, "pressure step other than");
}
