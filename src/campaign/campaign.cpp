#include "gradfric/campaign/campaign.hpp"

namespace gradfric::campaign {

Grading Campaign::pointGrading(int p) const {
  Grading g = gradingOf(sweep.points[p], baseGrading.bands);
  // The property fields: the same at every point, or the point's value of -ensemble_field.
  g.fields = pointFields.empty() ? baseGrading.fields : pointFields[p];
  return g;
}

}  // namespace gradfric::campaign
