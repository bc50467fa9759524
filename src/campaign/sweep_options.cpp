// Reading the swept lists of a scene (include/gradfric/campaign/sweep_options.hpp).
#include "gradfric/campaign/sweep_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/grading.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <string>

namespace gradfric::campaign {

SweepLists readSweepLists(OptionReader& ens) {
  SweepLists lists;
  lists.delta = ens.realList("delta", {}, "1", "sweep of the grading amplitude Delta (empty: -grading_delta alone)");
  lists.theta = ens.realList("theta", {}, "degree", "sweep of the sliding angle (empty: -plate_theta alone)");
  lists.sigma = ens.realList("sigma", {}, "1",
                             "sweep of the relative dispersion, sets sigma_s and sigma_k (empty: -surface_sigma_s/_k)");
  lists.property = ens.choiceList("property", {}, {"E", "friction", "both"},
                                  "sweep of the graded property (empty: -grading_property alone)");
  lists.profile = ens.choiceList("profile", {}, gradingProfileNames(),
                                 "sweep of the grading profile (empty: -grading_profile alone)");
  lists.fieldParameter = ens.text("field", "",
                                  "sweep of one scalar parameter of a property field, <property>_<parameter>: "
                                  "mu_delta, E_exponent, mu_period, p_position, ... (docs/fields.md)");
  lists.fieldValues = ens.realList("field_values", {}, "(the parameter's)", "the values of -ensemble_field, innermost loop");
  for (double d : lists.delta)
    if (!(std::fabs(d) < 1.0)) throw InputError(ens.fullName("delta"), formatReal(d), "values with |Delta| < 1");
  return lists;
}

// One PlateFields per value of -ensemble_field_values (empty without a field sweep); the value
// that makes the field uniform, if any, becomes the sweep's reference.
std::vector<std::shared_ptr<const PlateFields>> fieldsPerValue(SweepLists* lists,
                                                               const std::shared_ptr<const PlateFields>& fields) {
  const bool named = !lists->fieldParameter.empty(), valued = !lists->fieldValues.empty();
  if (named != valued)
    throw InputError(named ? "-ensemble_field_values" : "-ensemble_field", "(not set)",
                     "both -ensemble_field and -ensemble_field_values, or neither");
  std::vector<std::shared_ptr<const PlateFields>> perValue;
  for (double v : lists->fieldValues) {
    try {
      perValue.push_back(withParameter(fields, lists->fieldParameter, v));
    } catch (const std::invalid_argument& e) {
      throw InputError("-ensemble_field", lists->fieldParameter, e.what());
    }
  }
  if (!perValue.empty()) {
    const PlateFields& f = *perValue.front();
    const std::string& name = lists->fieldParameter;
    const auto* swept = name.rfind("E_", 0) == 0 ? f.modulus.get() : name.rfind("p_", 0) == 0 ? f.pressure.get()
                        : name.rfind("mu_k_", 0) == 0 ? f.muKinetic.get() : f.muStatic.get();
    const bool amplitude = name.size() > 6 && name.compare(name.size() - 6, 6, "_delta") == 0 &&
                           swept->shape != FieldShape::Exponential && swept->shape != FieldShape::Bands &&
                           swept->shape != FieldShape::Map;
    const bool rate = name.size() > 9 && name.compare(name.size() - 9, 9, "_exponent") == 0 &&
                      swept->shape == FieldShape::Exponential;
    lists->fieldHasNeutral = amplitude || rate;
    lists->fieldNeutral = 0.0;
  }
  return perValue;
}

void checkSweepLists(const SweepLists& lists, const Grading& base) {
  auto name = [](const char* n) { return std::string("-ensemble_") + n; };
  for (double t : lists.theta)
    if (!std::isfinite(t)) throw InputError(name("theta"), formatReal(t), "finite angles [degree]");
  for (double s : lists.sigma)
    if (!(s >= 0.0 && s <= 0.5)) throw InputError(name("sigma"), formatReal(s), "values with 0 <= sigma <= 0.5");
  const bool anyProfile = base.profile != GradingProfile::None ||
                          std::any_of(lists.profile.begin(), lists.profile.end(), [](auto& p) { return p != "none"; });
  const char* needProfile = "only with a grading profile: set -grading_profile linear or triangular (it is none)";
  if (!lists.delta.empty() && !anyProfile) throw InputError(name("delta"), "(a list)", needProfile);
  if (!lists.property.empty() && !anyProfile) throw InputError(name("property"), "(a list)", needProfile);
}

bool anySwept(const SweepLists& lists) {
  return !lists.delta.empty() || !lists.theta.empty() || !lists.sigma.empty() || !lists.property.empty() ||
         !lists.profile.empty() || !lists.fieldParameter.empty() || !lists.fieldValues.empty();
}

io::SweepTable sweepColumns(const Sweep& sweep) {
  io::SweepTable table;
  table.axes = sweep.axes;
  for (const auto& q : sweep.points) {
    table.delta.push_back(q.delta);
    table.theta.push_back(q.theta);
    table.sigma.push_back(q.sigma);
    table.sigmaKinetic.push_back(q.sigmaKinetic);
    table.property.push_back(q.property);
    table.profile.push_back(q.profile);
  }
  table.referencePoint = sweep.reference;
  return table;
}

void refuseOverriddenBaseOptions(const RunParameters& record) {
  const char* const pairs[][2] = {{"-ensemble_delta", "-grading_delta"},       {"-ensemble_property", "-grading_property"},
                                  {"-ensemble_profile", "-grading_profile"},   {"-ensemble_theta", "-plate_theta"},
                                  {"-ensemble_sigma", "-surface_sigma_s"},     {"-ensemble_sigma", "-surface_sigma_k"}};
  const auto set = [&](const char* name) {
    const ResolvedOption* o = record.find(name);
    return o && o->origin == OptionOrigin::User ? o : nullptr;
  };
  for (const auto& [list, base] : pairs)
    if (const ResolvedOption* b = set(base); b && set(list))
      throw InputError(base, b->value, std::string("not together with ") + list + " = " + set(list)->value +
                                           ", which sets it at every sweep point: give one of the two");
}

}  // namespace gradfric::campaign
