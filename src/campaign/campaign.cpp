#include "gradfric/campaign/campaign.hpp"

#include "gradfric/core/options.hpp"

namespace gradfric::campaign {

Grading Campaign::pointGrading(int p) const {
  Grading g = gradingOf(sweep.points[p], baseGrading.bands);
  // The property fields: the same at every point, or the point's value of -ensemble_field.
  g.fields = pointFields.empty() ? baseGrading.fields : pointFields[p];
  return g;
}

void Campaign::recordOptions(const RunParameters& record, const std::set<std::string>& runControl) {
  for (const io::Attribute& a : io::optionAttributes(record)) {
    const std::string name = "-" + a.name;
    if (name.rfind("-ensemble_target", 0) == 0 && !target.active()) continue;
    if (name == "-ensemble_extend" && !extend) continue;
    (runControl.count(name) ? runAttributes : sceneAttributes).push_back(a);
  }
}

}  // namespace gradfric::campaign
