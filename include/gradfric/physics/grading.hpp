#pragma once
// Lateral grading of a material property along x (paper Eq. 3-5): a stepwise profile of N bands.
// Pure arithmetic, no PETSc: unit-testable on its own and shared by the SBM and the FEM.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace gradfric {

enum class GradingProfile { None, Linear, Triangular };
enum class GradedProperty { YoungsModulus, Friction, Both };

struct PlateFields;

struct Grading {
  GradingProfile profile = GradingProfile::None;
  GradedProperty property = GradedProperty::YoungsModulus;
  double delta = 0.0;  // relative variation at the edge (linear) or centre (triangular), |delta| < 1
  int bands = 10;      // N >= 2
  // Property fields (-field_* options, field.hpp): each replaces the grading of its property.
  // Sample through PropertySampler (property_sampler.hpp), which falls back on the bands below.
  std::shared_ptr<const PlateFields> fields = nullptr;

  bool active() const { return profile != GradingProfile::None && delta != 0.0; }
  bool gradesModulus() const { return active() && property != GradedProperty::Friction; }
  bool gradesFriction() const { return active() && property != GradedProperty::YoungsModulus; }

  // phi_i / phi_0 for band i = 0..N-1 (Eq. 4 linear, Eq. 5 triangular).
  double bandFactor(int band) const {
    if (!active()) return 1.0;
    const double s = 2.0 * band / (bands - 1) - 1.0;  // -1 .. 1 across the plate
    if (profile == GradingProfile::Linear) return 1.0 + delta * s;
    return 1.0 + delta * (1.0 - 2.0 * std::fabs(s));
  }
  // The band holding the point at x/L in [0, 1] (the right edge belongs to the last band).
  int bandOf(double xOverL) const {
    const int band = static_cast<int>(std::floor(xOverL * bands));
    return std::clamp(band, 0, bands - 1);
  }
  double modulusFactor(double xOverL) const { return gradesModulus() ? bandFactor(bandOf(xOverL)) : 1.0; }
  double frictionFactor(double xOverL) const { return gradesFriction() ? bandFactor(bandOf(xOverL)) : 1.0; }
};

const char* toString(GradingProfile profile);
const char* toString(GradedProperty property);
std::string describe(const Grading& grading);

}  // namespace gradfric
