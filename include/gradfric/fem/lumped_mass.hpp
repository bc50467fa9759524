#pragma once
// The lumped (row-sum) mass of the plate: rho V_cell / 8 to each vertex of every cell; the
// explicit scheme's acceleration is M^-1 force, its kinetic energy (1/2) v . M v.
#include "gradfric/fem/plate_mesh.hpp"

#include <vector>

namespace gradfric::fem {

class LumpedMass {
public:
  LumpedMass(const PlateMesh& mesh, double density);

  const std::vector<double>& perBlock() const { return mass_; }  // per owned block [kg]
  const std::vector<double>& inversePerBlock() const { return inverse_; }
  double total() const;  // over ranks [kg]
  double kineticEnergy(Vec X) const;  // of the state X, over ranks [J]

private:
  MPI_Comm comm_;
  std::vector<double> mass_, inverse_;
};

}  // namespace gradfric::fem
