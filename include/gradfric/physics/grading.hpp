#pragma once
// Lateral grading of a material property along x (paper Eq. 3-5): a stepwise profile of N bands.
// Pure arithmetic, no PETSc: unit-testable on its own and shared by the SBM and the FEM.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace gradfric {

enum class GradingProfile { None, Linear, Triangular };
enum class GradedProperty { YoungsModulus, Friction, Both };

// The profiles, one row each: its name (the options' spelling) and its band factor phi_i / phi_0
// at the band's coordinate s = -1 .. 1 across the plate. A new profile is one row here (and one
// enumerator); every option, sweep list and file reader takes its names from this table.
struct GradingProfileRow {
  GradingProfile profile;
  const char* name;
  double (*factor)(double s, double delta);
};
inline constexpr GradingProfileRow kGradingProfiles[] = {
    {GradingProfile::None, "none", [](double, double) { return 1.0; }},
    {GradingProfile::Linear, "linear", [](double s, double delta) { return 1.0 + delta * s; }},  // Eq. 4
    {GradingProfile::Triangular, "triangular",
     [](double s, double delta) { return 1.0 + delta * (1.0 - 2.0 * std::fabs(s)); }},  // Eq. 5
};
// The row of a profile.
const GradingProfileRow& gradingProfileRow(GradingProfile profile);
// The profile named `name`; std::invalid_argument for a name not in the table.
GradingProfile parseGradingProfile(const std::string& name);
// Every name, "none" first: the allowed values of -grading_profile and -ensemble_profile.
std::vector<std::string> gradingProfileNames();

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

  // phi_i / phi_0 for band i = 0..N-1: the profile's row of kGradingProfiles.
  double bandFactor(int band) const {
    if (!active()) return 1.0;
    const double s = 2.0 * band / (bands - 1) - 1.0;  // -1 .. 1 across the plate
    return gradingProfileRow(profile).factor(s, delta);
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
