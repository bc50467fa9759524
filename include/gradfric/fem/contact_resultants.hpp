#pragma once
// Resultants of the contact tractions of the last right-hand side evaluation, over all ranks:
// the forces, the tilting moment of the contact pressure about the bottom face's centre line,
// and the pressure along the trailing (x = 0) and leading (x = L) edges. The moment balance of a
// plate driven at its top at height H: sum over the contact nodes of (x - L/2) p_c A equals
// H times the tangential force, up to inertia (docs/fem.md, "Trailing-edge unloading").
#include "gradfric/fem/plate_model.hpp"

namespace gradfric::fem {

struct ContactResultants {
  double forceX = 0, forceY = 0, normalForce = 0;  // [N], of the contact on the plate
  double momentAboutY = 0;  // sum (x - L/2) p_c A [N m]: > 0 when the leading edge x = L carries more
  double momentAboutX = 0;  // sum (y - L/2) p_c A [N m]
  double trailingEdgePressure = 0, leadingEdgePressure = 0;  // mean p_c of the nodes on x = 0, x = L [Pa]
  double centrePressure = 0;  // mean p_c of the nodes on the line x = L/2 (or the nearest line) [Pa]
};

ContactResultants contactResultants(const PlateModel& model);

}  // namespace gradfric::fem
