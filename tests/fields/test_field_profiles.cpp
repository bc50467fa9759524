// Property fields (physics/field.hpp, property_sampler.hpp): the paper's gradings through the new
// description equal the bands bit for bit; profiles, directions, maps and normalisation.
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gradfric;

namespace {

constexpr double kLength = 5e-3;

std::shared_ptr<const PlateFields> fieldsOf(const PropertyField& f, bool modulus, bool friction) {
  auto shared = std::make_shared<const PropertyField>(f);
  PlateFields fields;
  if (modulus) fields.modulus = shared;
  if (friction) fields.muStatic = fields.muKinetic = shared;
  return std::make_shared<const PlateFields>(fields);
}

// The paper's grading as a field: the same profile and bands along x.
PropertyField paperField(const Grading& g) {
  PropertyField f;
  f.shape = g.profile == GradingProfile::Linear ? FieldShape::Linear : FieldShape::Triangular;
  f.delta = g.delta;
  f.bands = g.bands;
  f.length = kLength;
  return f;
}

double meanOver(const PropertySampler& s, int n, double (PropertySampler::*get)(double, double) const) {
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) sum += (s.*get)((i + 0.5) / n, (j + 0.5) / n);
  return sum / (double(n) * n);
}

}  // namespace

TEST(Fields, PaperGradingsThroughTheFieldPathAreBitwiseTheBands) {
  for (auto profile : {GradingProfile::Linear, GradingProfile::Triangular})
    for (auto property : {GradedProperty::YoungsModulus, GradedProperty::Friction, GradedProperty::Both})
      for (double delta : {-0.4, -0.1, 0.2, 0.35})
        for (int bands : {2, 10, 11, 37})
          for (int nb : {7, 60, 120}) {
            const Grading old{profile, property, delta, bands};
            Grading viaField;  // no -grading_*: the field gives the same property
            viaField.fields = fieldsOf(paperField(old), old.gradesModulus(), old.gradesFriction());
            const PropertySampler a(old, nb, nb), b(viaField, nb, nb);
            for (int r = 0; r < nb; r += 3)
              for (int c = 0; c < nb; ++c) {
                const double u = (c + 0.5) / nb, v = (r + 0.5) / nb;
                ASSERT_EQ(a.modulus(u, v), b.modulus(u, v));
                ASSERT_EQ(a.muStatic(u, v), b.muStatic(u, v));
                ASSERT_EQ(a.muKinetic(u, v), b.muKinetic(u, v));
                ASSERT_EQ(a.modulus(u, v), old.modulusFactor(u));  // the sampler keeps the old bands
                ASSERT_EQ(a.muStatic(u, v), old.frictionFactor(u));
              }
          }
}

TEST(Fields, ProfilesAlongDirectionsAndRadially) {
  PropertyField f;
  f.length = kLength;
  f.shape = FieldShape::Linear;
  f.delta = 0.2;
  EXPECT_DOUBLE_EQ(f.profile(0.0, 0.3), 0.8);
  EXPECT_DOUBLE_EQ(f.profile(1.0, 0.9), 1.2);
  f.angle = 90;  // along y
  EXPECT_DOUBLE_EQ(f.profile(0.3, 0.0), 0.8);
  EXPECT_DOUBLE_EQ(f.profile(0.7, 1.0), 1.2);
  EXPECT_TRUE(f.variesAlongY());
  f.angle = 180;  // reversed
  EXPECT_DOUBLE_EQ(f.profile(0.0, 0.5), 1.2);
  EXPECT_FALSE(f.variesAlongY());
  f.angle = 45;  // the diagonal: corners (0,0) and (1,1) are the ends, the centre is the mean
  EXPECT_NEAR(f.profile(0.0, 0.0), 0.8, 1e-15);
  EXPECT_NEAR(f.profile(1.0, 1.0), 1.2, 1e-15);
  EXPECT_NEAR(f.profile(1.0, 0.0), 1.0, 1e-15);
  f.angle = 0;
  f.radial = true;
  f.centreX = f.centreY = kLength / 2;
  EXPECT_DOUBLE_EQ(f.profile(0.5, 0.5), 0.8);
  EXPECT_NEAR(f.profile(1.0, 1.0), 1.2, 1e-15);
  EXPECT_NEAR(f.profile(0.5 + 0.25, 0.5), f.profile(0.5, 0.25), 1e-15);  // depends on the distance only

  PropertyField e;
  e.length = kLength;
  e.shape = FieldShape::Exponential;
  e.exponent = std::log(2.0);  // f doubles across the plate
  EXPECT_NEAR(e.profile(1.0, 0.5) / e.profile(0.0, 0.5), 2.0, 1e-14);
  EXPECT_DOUBLE_EQ(e.profile(0.5, 0.1), 1.0);

  PropertyField p;
  p.length = kLength;
  p.shape = FieldShape::Power;
  p.delta = 0.3;
  p.exponent = 2;
  EXPECT_DOUBLE_EQ(p.profile(0.0, 0.5), 0.7);
  EXPECT_DOUBLE_EQ(p.profile(1.0, 0.5), 1.3);
  EXPECT_DOUBLE_EQ(p.profile(0.5, 0.5), 1.0 + 0.3 * (2 * 0.25 - 1));

  PropertyField s;
  s.length = kLength;
  s.shape = FieldShape::Stripes;
  s.delta = 0.5;
  s.period = 1e-3;
  s.duty = 0.25;
  EXPECT_DOUBLE_EQ(s.profile(0.1 / 5, 0.5), 1.5);   // x = 0.1 mm: in the first stripe
  EXPECT_DOUBLE_EQ(s.profile(0.5 / 5, 0.5), 1.0);   // x = 0.5 mm: between stripes
  EXPECT_DOUBLE_EQ(s.profile(1.1 / 5, 0.5), 1.5);   // the next period

  PropertyField t;
  t.length = kLength;
  t.shape = FieldShape::Bands;
  t.table = {1.0, 2.0, 3.0};
  EXPECT_EQ(t.profile(0.1, 0.5), 1.0);
  EXPECT_EQ(t.profile(0.5, 0.5), 2.0);
  EXPECT_EQ(t.profile(1.0, 0.5), 3.0);  // the right edge belongs to the last band
}

TEST(Fields, BilinearMapReproducesALinearProfileOnThePlate) {
  // The shipped input/fields/linear_ramp.h5: 18 pixels, one beyond the plate on each side.
  auto map = std::make_shared<FieldMap>();
  map->nx = map->ny = 18;
  const double dx = kLength / 16;
  map->x0 = map->y0 = -dx;
  map->x1 = map->y1 = kLength + dx;
  for (int j = 0; j < 18; ++j)
    for (int i = 0; i < 18; ++i) map->values.push_back(1.0 + 0.2 * (2.0 * (-dx + (i + 0.5) * dx) / kLength - 1.0));
  PropertyField m;
  m.length = kLength;
  m.shape = FieldShape::Map;
  m.map = map;
  PropertyField linear;
  linear.length = kLength;
  linear.shape = FieldShape::Linear;
  linear.delta = 0.2;
  for (double u = 0; u <= 1.0; u += 0.0137)
    for (double v : {0.0, 0.31, 1.0}) EXPECT_NEAR(m.profile(u, v), linear.profile(u, v), 1e-14);
  // Beyond the outer pixel centres the map is constant (no extrapolation).
  EXPECT_DOUBLE_EQ(map->at(-dx, 0), map->values[0]);
}

TEST(Fields, NormalisationKeepsThePlatesMean) {
  PropertyField s;
  s.length = kLength;
  s.shape = FieldShape::Stripes;
  s.delta = 0.3;
  s.period = 1e-3;
  s.duty = 0.3;
  s.angle = 30;
  s.normalise = true;
  PropertyField step;
  step.length = kLength;
  step.shape = FieldShape::Step;
  step.delta = 0.4;
  step.position = 1.3e-3;
  step.normalise = true;
  PropertyField e;
  e.length = kLength;
  e.shape = FieldShape::Exponential;
  e.exponent = 1.5;
  e.radial = true;
  e.centreX = 1e-3;
  e.centreY = 4e-3;
  e.normalise = true;
  for (const PropertyField* f : {&s, &step, &e})
    for (int n : {40, 97}) {
      PlateFields fields;
      fields.modulus = std::make_shared<const PropertyField>(*f);
      fields.pressure = fields.modulus;
      Grading g;
      g.fields = std::make_shared<const PlateFields>(fields);
      const PropertySampler sampler(g, n, n);
      EXPECT_NEAR(meanOver(sampler, n, &PropertySampler::modulus), 1.0, 1e-12) << f->describe();
      EXPECT_NEAR(meanOver(sampler, n, &PropertySampler::pressure), 1.0, 1e-12) << f->describe();
      PropertyField raw = *f;
      raw.normalise = false;
      EXPECT_GT(std::fabs(raw.scaleFor(n, n) - f->scaleFor(n, n)), 1e-3);  // the test is not vacuous
    }
}

TEST(Fields, SiteChecksFindTheFirstBadSite) {
  Plate plate;
  PropertyField f;
  f.length = plate.length;
  f.shape = FieldShape::Linear;
  f.delta = 1.5;  // negative E on the left
  PlateFields fields;
  fields.modulus = std::make_shared<const PropertyField>(f);
  Grading g;
  g.fields = std::make_shared<const PlateFields>(fields);
  SiteProblem p = checkSites(g, plate, 10, 10);
  EXPECT_EQ(p.property, "E");
  EXPECT_NEAR(p.where.x, 0.25e-3, 1e-15);  // the first block centre
  EXPECT_LT(p.where.value, 0.0);
  // mu_k above mu_s where only mu_k is raised.
  PropertyField k;
  k.length = plate.length;
  k.shape = FieldShape::Step;
  k.delta = 0.7;  // 0.6 x 1.7 = 1.02 > 1 beyond x = 4 mm
  k.position = 4e-3;
  PlateFields kinetic;
  kinetic.muKinetic = std::make_shared<const PropertyField>(k);
  g.fields = std::make_shared<const PlateFields>(kinetic);
  p = checkSites(g, plate, 10, 10);
  EXPECT_EQ(p.property, "mu_k");
  EXPECT_GT(p.where.x, 4e-3);
  k.delta = 0.6;  // 0.96: fine
  kinetic.muKinetic = std::make_shared<const PropertyField>(k);
  g.fields = std::make_shared<const PlateFields>(kinetic);
  EXPECT_TRUE(checkSites(g, plate, 10, 10).property.empty());
}
