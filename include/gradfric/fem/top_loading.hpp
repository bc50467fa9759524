#pragma once
// The loading of the plate's top face: step 1, the pressure p ramped linearly over rampTime, then
// held; step 2, the top also slides tangentially at v in the direction theta (its tangential
// velocity imposed, its vertical motion free). The slider's force on the top and the top's mean
// vertical displacement are accounted for the energy balance.
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/fem/plate_mesh.hpp"

#include <functional>
#include <vector>

namespace gradfric::fem {

class TopLoading {
public:
  // pressureShape(x, y): the local pressure over p (a static pressure field, -field_p_*); empty: uniform.
  TopLoading(const PlateMesh& mesh, double pressure, double rampTime, double velocity, double angleDegrees,
             const std::function<double(double, double)>& pressureShape = {});

  double pressureAt(double t, bool sliding) const;
  // Adds the pressure force at t to the force slots of F (global state layout).
  void addPressure(double t, bool sliding, Vec F) const;
  // Sets the top's tangential velocity in the state X to the slider's (the start of step 2).
  void startSliding(Vec X) const;
  // In step 2, the slider holds the top's tangential acceleration at zero: zeroes it in the RHS
  // F (accelerations) and returns the force it takes, -m a, in driveX, driveY [N], on this rank.
  void constrainTangential(const std::vector<double>& mass, Vec F, ExactSum* driveX, ExactSum* driveY) const;
  // Sum over the top nodes of area * u_z of X on this rank [m^3] (the pressure's work is -p dZ).
  ExactSum areaWeightedLift(Vec X) const;  // this rank's share
  double area() const;  // sum of the top nodal areas over ranks (= L^2)

private:
  struct Node {
    PetscInt block;
    double area;  // nodal area, times the pressure shape when there is one (what p pushes on)
  };
  MPI_Comm comm_;
  double pressure_, rampTime_, velocityX_, velocityY_;
  std::vector<Node> nodes_;
};

}  // namespace gradfric::fem
