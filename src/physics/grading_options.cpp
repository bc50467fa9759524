#include "gradfric/physics/grading_options.hpp"

#include "gradfric/core/input_error.hpp"

#include <cmath>

namespace gradfric {

Grading readGrading(MPI_Comm comm, RunParameters* record) {
  OptionReader options(comm, "grading_", "Lateral grading of the plate (paper Eq. 3-5)", record);
  Grading g;
  const std::string profile =
      options.choice("profile", "none", {"none", "linear", "triangular"}, "stepwise grading profile along x");
  const std::string property = options.choice("property", "E", {"E", "friction", "both"},
                                              "graded property: Young's modulus, local friction coefficients, or both");
  g.delta = options.real("delta", 0.0, "1", "relative variation Delta (edge for linear, centre for triangular)");
  g.bands = static_cast<int>(options.integer("bands", 10, "1", "number N of homogeneous bands across the plate"));
  g.profile = profile == "linear" ? GradingProfile::Linear
              : profile == "triangular" ? GradingProfile::Triangular
                                        : GradingProfile::None;
  g.property = property == "friction" ? GradedProperty::Friction
               : property == "both"   ? GradedProperty::Both
                                      : GradedProperty::YoungsModulus;
  // |Delta| >= 1 makes the property zero or negative somewhere.
  if (!(std::fabs(g.delta) < 1.0)) throw InputError(options.fullName("delta"), formatReal(g.delta), "|Delta| < 1");
  options.requireAtLeast("bands", g.bands, 2);
  return g;
}

}  // namespace gradfric
