#pragma once
// How many realisations a campaign runs per point, for either model: a fixed count
// (-ensemble_realisations) or a precision target (-ensemble_target, _type, _min, _max), read and
// checked one way for the spring-block ensemble and the FEM sweep.
#include "gradfric/campaign/campaign.hpp"
#include "gradfric/core/options.hpp"

#include <string>

namespace gradfric::campaign {

// The count and the target as a campaign takes them (Campaign::realisations and ::target).
struct RealisationPlan {
  int realisations = 1;  // per point; with a target, its cap (the file holds up to the cap)
  PrecisionTarget target;
};

// Reads the options from a reader of prefix "ensemble_" (-help lists them there; `meaning` says
// what a realisation is in the model) and, unless -help was asked, checks them. InputError naming
// the option.
RealisationPlan readRealisationOptions(OptionReader& ensemble, const std::string& meaning);

// Once the sweep is built: refuses more than 2e9 tasks and a variation target on a sweep with a
// graded point that has no non-graded point to compare with.
void checkRealisationPlan(const Campaign& c);

}  // namespace gradfric::campaign
