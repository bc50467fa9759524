#pragma once
// The loading of the plate's top face (the layer of the loading protocol's loads): step 1, the
// pressure p(t) of the protocol on each top node's load (its area times a static pressure field's
// factor); step 2, the top also slides tangentially at v in the direction theta (its tangential
// velocity imposed, its vertical motion free). The slider's force on the top and the top's mean
// vertical displacement are accounted for the energy balance.
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/plate_properties.hpp"

#include <vector>

namespace gradfric::fem {

class TopLoading : public Layer {
public:
  TopLoading(const PlateMesh& mesh, const PlateProperties& properties);

  // The layer: the pressure ctx.pressure on the top nodes' loads, and the top's lift (sums.topZ);
  // while sliding, the slider holds the top's tangential acceleration at zero and takes the force
  // -m a (sums.driveX, driveY).
  const char* name() const override { return "top loading"; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void addDeadLoad(Vec F) const override;  // the pressure p of the plate
  void constrain(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  std::string describe() const override;
  void writeProperties(PropertySink& sink) const override;

  // Adds the force of the pressure p to the force slots of F (global state layout).
  void addPressure(double p, Vec F) const;
  // Sets the top's tangential velocity in the state X to the slider's (the start of step 2).
  void startSliding(Vec X) const;
  double area() const;  // sum of the top nodal areas over ranks (= L^2)

private:
  MPI_Comm comm_;
  const PlateProperties& properties_;
  double velocityX_, velocityY_;
};

}  // namespace gradfric::fem
