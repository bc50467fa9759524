// The realisations of a campaign (include/gradfric/campaign/realisation_options.hpp).
#include "gradfric/campaign/realisation_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"

namespace gradfric::campaign {

namespace {

// -ensemble_target and its companions: a precision instead of a count.
void checkTarget(const OptionReader& ens, double target, const std::string& type, PetscInt first, PetscInt cap,
                 PetscInt realisations, RealisationPlan* c) {
  if (!(target >= 0.0 && target < 1.0))
    throw InputError(ens.fullName("target"), formatReal(target),
                     "0 (no target) or a half-width 0 < target < 1 (a fraction for relative and variation)");
  if (target == 0.0) {
    for (const char* name : {"target_type", "target_min", "target_max"})
      if (ens.wasSet(name))
        throw InputError(ens.fullName(name), "(set)", "only together with -ensemble_target > 0");
    return;
  }
  // A scene's count becomes the first batch of a target run (so a target can be added to it).
  if (ens.wasSet("realisations")) {
    if (ens.wasSet("target_min"))
      throw InputError(ens.fullName("target_min"), std::to_string(first),
                       "not together with -ensemble_realisations under -ensemble_target (both set the first batch)");
    if (realisations < 2)
      throw InputError(ens.fullName("realisations"), std::to_string(realisations),
                       "at least 2 under -ensemble_target (it is the first batch)");
    first = realisations;
  }
  if (first > cap)
    throw InputError(ens.fullName(ens.wasSet("realisations") ? "realisations" : "target_min"), std::to_string(first),
                     "at most -ensemble_target_max = " + std::to_string(cap) + " (the first batch)");
  c->target.kind = targetKindOf(type);
  c->target.halfWidth = target;
  c->target.first = static_cast<int>(first);
  c->target.cap = static_cast<int>(cap);
}

}  // namespace

RealisationPlan readRealisationOptions(OptionReader& ens, const std::string& meaning) {
  RealisationPlan plan;
  const PetscInt realisations =
      ens.integer("realisations", 1, 1, 10000000, "1", "realisations R per sweep point (" + meaning + ")");
  const double target = ens.real(
      "target", 0.0, "1",
      "precision on demand: run batches until the 95 % CI half-width of every point's -ensemble_target_type "
      "quantity is at most this (0: a fixed count, -ensemble_realisations)");
  const std::string targetType = ens.choice(
      "target_type", "absolute", {"absolute", "relative", "variation"},
      "what -ensemble_target bounds: the CI of mean mu_s, that CI over |mean mu_s|, or the CI of the relative "
      "variation (mu_s - mu_s,0) / mu_s,0 against the non-graded point");
  const PetscInt targetMin =
      ens.integer("target_min", 8, 2, 10000000, "1",
                  "with -ensemble_target: realisations per point of the first batch (-ensemble_realisations if set)");
  const PetscInt targetMax =
      ens.integer("target_max", 200, 2, 10000000, "1",
                  "with -ensemble_target: at most this many realisations per point");
  if (helpRequested()) return plan;
  ens.requireAtLeast("realisations", realisations, 1);
  checkTarget(ens, target, targetType, targetMin, targetMax, realisations, &plan);
  plan.realisations = plan.target.active() ? plan.target.cap : static_cast<int>(realisations);
  return plan;
}

void checkRealisationPlan(const Campaign& c) {
  if (static_cast<double>(c.points()) * c.realisations > 2e9)
    throw InputError("too many tasks: sweep points x realisations > 2e9");
  if (c.target.active() && c.target.kind == TargetKind::Variation)
    for (int p = 0; p < c.points(); ++p)
      if (c.sweep.reference[p] < 0)
        throw InputError("-ensemble_target_type", "variation",
                         "sweeps with a non-graded point for every graded one (point " + std::to_string(p) +
                             " has none: add 0 to -ensemble_delta)");
}

}  // namespace gradfric::campaign
