#pragma once
// The properties the layers used (Layer::writeProperties: E per cell, mu_s and mu_k per bottom
// node, p per top node, ...) along the plate's middle, gathered on rank 0 for the history file's
// /properties: a per-cell field at the bottom-layer cells of row ny/2 (one value per column,
// [nx]), a per-node field at the nodes of node row ny/2 of its face ([nx + 1]). These are the
// physics' own values (a node's friction is the area-weighted mean of its faces'), not the fields
// sampled again.
#include "gradfric/fem/plate_model.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

struct PropertyProfile {
  std::string name, unit, description;
  bool perNode = false;        // on node_x [nx + 1], else on the column centres x [nx]
  std::vector<double> values;  // on rank 0 (NaN where no rank had a value)
};

// Collective: every active layer's properties, in the list's order.
std::vector<PropertyProfile> gatherPropertyProfiles(const PlateModel& model);

}  // namespace gradfric::fem
