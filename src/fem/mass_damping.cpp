#include "gradfric/fem/mass_damping.hpp"

#include <cstdio>

namespace gradfric::fem {

MassDamping::MassDamping(const FemParameters& q, PetscInt ownedBlocks)
    : settle_(q.settleDamping), slide_(q.slideDamping), peak_(q.peakDamping), step_(ownedBlocks, 0.0),
      work_(ownedBlocks, 0.0) {}

void MassDamping::archive(StateArchive& a) {
  a.fixedField("mass_damping.step", step_);
  a.fixedField("mass_damping.work", work_);
}

LayerWork MassDamping::work() const {
  LayerWork w;
  for (double e : work_) w.rankShare.add(e);
  return w;
}

std::string MassDamping::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "mass-proportional: %.3g 1/s settling, %.3g 1/s sliding, %.3g 1/s towards the slider from the peak",
                settle_, slide_, peak_);
  return text;
}

}  // namespace gradfric::fem
