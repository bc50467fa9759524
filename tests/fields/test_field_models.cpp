// Both ways of saying a paper grading give the same spring-block run bit for bit; a map of a
// linear profile runs like the profile; a step of friction starts slipping on its weaker side;
// a pressure field enters the friction strengths.
#include "../sbm/sbm_support.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/sbm/lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gradfric;
using namespace gradfric::sbm;

namespace {

std::shared_ptr<const PlateFields> frictionFields(const PropertyField& f) {
  PlateFields fields;
  fields.muStatic = fields.muKinetic = std::make_shared<const PropertyField>(f);
  return std::make_shared<const PlateFields>(fields);
}

Result run(const Parameters& p, const Grading& g, std::uint32_t realisation = 0) {
  Request q = sbm::testing::defaultRequest(p);
  return simulate(p, g, q, StreamKey{7, 1, realisation});
}

void expectSameRun(const Result& a, const Result& b) {
  EXPECT_EQ(a.friction.muStatic, b.friction.muStatic);
  EXPECT_EQ(a.friction.muKinetic, b.friction.muKinetic);
  EXPECT_EQ(a.friction.peakTime, b.friction.peakTime);
  EXPECT_EQ(a.steps, b.steps);
  ASSERT_EQ(a.firstSlipTime.size(), b.firstSlipTime.size());
  for (std::size_t i = 0; i < a.firstSlipTime.size(); ++i)
    if (!(std::isnan(a.firstSlipTime[i]) && std::isnan(b.firstSlipTime[i]))) {
      ASSERT_EQ(a.firstSlipTime[i], b.firstSlipTime[i]);
    }
}

}  // namespace

TEST(FieldModels, PaperGradingsRunBitwiseTheSameThroughFields) {
  struct Case {
    GradingProfile profile;
    GradedProperty property;
    double delta;
  };
  for (const Case c : {Case{GradingProfile::Linear, GradedProperty::Friction, 0.2},
                       Case{GradingProfile::Triangular, GradedProperty::Both, -0.3},
                       Case{GradingProfile::Linear, GradedProperty::YoungsModulus, 0.4}}) {
    const Grading old{c.profile, c.property, c.delta, 10};
    PropertyField f;
    f.shape = c.profile == GradingProfile::Linear ? FieldShape::Linear : FieldShape::Triangular;
    f.delta = c.delta;
    f.bands = 10;
    f.length = Plate{}.length;
    PlateFields fields;
    auto shared = std::make_shared<const PropertyField>(f);
    if (old.gradesModulus()) fields.modulus = shared;
    if (old.gradesFriction()) fields.muStatic = fields.muKinetic = shared;
    Grading viaField;
    viaField.fields = std::make_shared<const PlateFields>(fields);
    for (double sigma : {0.0, 0.028}) {
      const Parameters p = sbm::testing::paperParameters(16, sigma, old);
      const Parameters q = sbm::testing::paperParameters(16, sigma, viaField);
      ASSERT_EQ(p.timeStep, q.timeStep);
      expectSameRun(run(p, old), run(q, viaField));
    }
  }
}

TEST(FieldModels, AMapOfALinearProfileRunsLikeTheProfile) {
  const double length = Plate{}.length, dx = length / 16;
  auto map = std::make_shared<FieldMap>();  // as input/fields/linear_ramp.h5
  map->nx = map->ny = 18;
  map->x0 = map->y0 = -dx;
  map->x1 = map->y1 = length + dx;
  for (int j = 0; j < 18; ++j)
    for (int i = 0; i < 18; ++i) map->values.push_back(1.0 + 0.2 * (2.0 * (-dx + (i + 0.5) * dx) / length - 1.0));
  PropertyField m;
  m.shape = FieldShape::Map;
  m.map = map;
  m.length = length;
  PropertyField linear;
  linear.shape = FieldShape::Linear;
  linear.delta = 0.2;
  linear.length = length;
  Grading viaMap, viaProfile;
  viaMap.fields = frictionFields(m);
  viaProfile.fields = frictionFields(linear);
  const Parameters p = sbm::testing::paperParameters(16, 0.028);
  const Result a = run(p, viaMap), b = run(p, viaProfile);
  EXPECT_NEAR(a.friction.muStatic, b.friction.muStatic, 1e-9);
  EXPECT_NEAR(a.friction.muKinetic, b.friction.muKinetic, 1e-9);
  // and the profile is graded: not the uniform plate's value
  EXPECT_GT(std::fabs(a.friction.muStatic - run(p, Grading{}).friction.muStatic), 1e-3);
}

TEST(FieldModels, AFrictionStepSlipsFirstOnItsWeakerSide) {
  const int nb = 20;
  const Parameters p = sbm::testing::paperParameters(nb, 0.028);
  for (double delta : {0.2, -0.2}) {
    PropertyField step;
    step.shape = FieldShape::Step;
    step.delta = delta;  // 1 - delta before x = 3 mm, 1 + delta beyond
    step.position = 3e-3;
    step.length = p.plate.length;
    Grading g;
    g.fields = frictionFields(step);
    for (std::uint32_t r = 0; r < 2; ++r) {
      const Result result = run(p, g, r);
      int first = -1;
      for (int i = 0; i < nb * nb; ++i)
        if (!std::isnan(result.firstSlipTime[i]) &&
            (first < 0 || result.firstSlipTime[i] < result.firstSlipTime[first]))
          first = i;
      ASSERT_GE(first, 0);
      const double x = (first % nb + 0.5) * p.spacing();
      if (delta > 0) EXPECT_LT(x, 3e-3) << "the weaker material is on the left";
      else EXPECT_GT(x, 3e-3) << "the weaker material is on the right";
    }
  }
}

TEST(FieldModels, APressureFieldScalesEachBlocksFrictionStrength) {
  const Parameters p = sbm::testing::paperParameters(12, 0.0);
  PropertyField pressure;
  pressure.shape = FieldShape::Linear;
  pressure.angle = 90;  // along y: one strength per block
  pressure.delta = 0.5;
  pressure.length = p.plate.length;
  PlateFields fields;
  fields.pressure = std::make_shared<const PropertyField>(pressure);
  Grading g;
  g.fields = std::make_shared<const PlateFields>(fields);
  const FrictionField f = buildFriction(p, g, StreamKey{1, 0, 0});
  EXPECT_EQ(f.layout, SiteLayout::PerSite);
  for (int r : {0, 5, 11}) {
    const double v = (r + 0.5) / 12;
    EXPECT_DOUBLE_EQ(f.staticAt(r, 3), p.plate.muStatic * p.normalForcePerBlock() * (1 + 0.5 * (2 * v - 1)));
    EXPECT_DOUBLE_EQ(f.kineticAt(r, 7), p.plate.muKinetic * p.normalForcePerBlock() * (1 + 0.5 * (2 * v - 1)));
  }
  // Without fields the strengths are one value, as before.
  EXPECT_EQ(buildFriction(p, Grading{}, StreamKey{1, 0, 0}).layout, SiteLayout::Uniform);
}
