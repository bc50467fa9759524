#pragma once
// The mass-proportional damping as a layer (sliding_damping.hpp: c_s/H while the plate settles,
// -fem_slide_damping while it slides, towards the slider's velocity from the peak on; the loading
// protocol says which). It acts on accelerations, so PlateModel applies ctx.damping in its M^-1
// pass (one pass over the state, not two) and hands this layer the pass's energy per block; the
// layer keeps each block's running sum, so the total is exact and the same on any partition.
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/parameters.hpp"

#include <vector>

namespace gradfric::fem {

class MassDamping : public Layer {
public:
  // On when any of the settling, sliding or peak damping is (resolved params).
  static bool wanted(const FemParameters& q) { return q.settleDamping > 0 || q.slideDamping > 0 || q.peakDamping > 0; }
  MassDamping(const FemParameters& resolved, PetscInt ownedBlocks);

  const char* name() const override { return "mass damping"; }
  void addForce(const LayerContext&, Vec, Vec, ContactSums&) override {}  // see above
  void postStep(double) override {
    for (std::size_t b = 0; b < work_.size(); ++b) work_[b] += step_[b];  // the rhs of the step saw its mid-step velocities
  }
  LayerWork work() const override;
  void archive(StateArchive& a) override;
  std::string describe() const override;

  // Per owned block, the energy the damping takes over the step of the last right-hand side
  // (power x dt), written by PlateModel's M^-1 pass.
  double* stepEnergy() { return step_.data(); }

private:
  double settle_, slide_, peak_;
  std::vector<double> step_, work_;
};

}  // namespace gradfric::fem
