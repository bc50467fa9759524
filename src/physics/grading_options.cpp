#include "gradfric/physics/grading_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <cmath>

namespace gradfric {

Grading readGrading(MPI_Comm comm, RunParameters* record) {
  OptionReader options(comm, "grading_", "Lateral grading of the plate (paper Eq. 3-5)", record);
  Grading g;
  const std::string profile =
      options.choice("profile", "none", gradingProfileNames(), "stepwise grading profile along x");
  const std::string property = options.choice("property", "E", {"E", "friction", "both"},
                                              "graded property: Young's modulus, local friction coefficients, or both");
  g.delta = options.real("delta", 0.0, "1", "relative variation Delta (edge for linear, centre for triangular)");
  g.bands = static_cast<int>(options.integer("bands", 10, 2, 4096, "1", "number N of homogeneous bands across the plate"));
  g.profile = parseGradingProfile(profile);
  g.property = property == "friction" ? GradedProperty::Friction
               : property == "both"   ? GradedProperty::Both
                                      : GradedProperty::YoungsModulus;
  // |Delta| >= 1 makes the property zero or negative somewhere.
  if (!(std::fabs(g.delta) < 1.0)) throw InputError(options.fullName("delta"), formatReal(g.delta), "|Delta| < 1");
  options.requireAtLeast("bands", g.bands, 2);
  // A Delta without a profile would silently run a uniform plate. An ensemble that sweeps the
  // profile (-ensemble_profile) applies Delta to its graded points: that is allowed.
  PetscBool profileSwept = PETSC_FALSE;
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-ensemble_profile", &profileSwept));
  if (g.profile == GradingProfile::None && g.delta != 0.0 && !profileSwept)
    throw InputError(options.fullName("profile"), profile,
                     "linear or triangular when -grading_delta is set (-grading_delta = " + formatReal(g.delta) +
                         " would be ignored: a uniform plate)");
  return g;
}

}  // namespace gradfric
