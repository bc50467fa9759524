#pragma once
// The swept lists of a scene (-ensemble_delta, _theta, _sigma, _property, _profile), read and
// checked one way for the spring-block ensemble (gradfric) and the FEM sweep (gradfric-fem), so
// that a scene line means the same in both and their results files have the same axes.
#include "gradfric/core/options.hpp"
#include "gradfric/campaign/sweep.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/grading.hpp"

#include <memory>
#include <vector>

namespace gradfric::campaign {

// Reads the lists from a reader of prefix "ensemble_" (-help lists them there), the field sweep
// (-ensemble_field, -ensemble_field_values) included; refuses |Delta| >= 1 at once (before a
// stable time step is computed from the sweep).
SweepLists readSweepLists(OptionReader& ensemble);

// The lists make sense together with the base grading: finite angles, 0 <= sigma <= 0.5, and a
// Delta or property sweep only with a grading profile.
void checkSweepLists(const SweepLists& lists, const Grading& base);

// A list replaces its base option at every point (-ensemble_delta sets -grading_delta): both set is
// refused (InputError naming the base option and its list) rather than one silently winning.
void refuseOverriddenBaseOptions(const RunParameters& record);

// One PlateFields per value of -ensemble_field_values (empty without a field sweep), each the
// scene's fields with the swept parameter set; records in `lists` the value that makes the field
// uniform, if any (the sweep's reference). InputError if only one of the two options is set or
// the parameter does not name a parameter of a field of the scene.
std::vector<std::shared_ptr<const PlateFields>> fieldsPerValue(SweepLists* lists,
                                                               const std::shared_ptr<const PlateFields>& fields);

// True if any list is given (the scene is a sweep).
bool anySwept(const SweepLists& lists);

// The /sweep columns of a results file (axes, one row per point, reference points), the same for
// both writers; the model fills the /properties fields.
io::SweepTable sweepColumns(const Sweep& sweep);

}  // namespace gradfric::campaign
