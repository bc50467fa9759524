#pragma once
// Bulk viscosity of the plate (Abaqus/Explicit's form, on by default there with b1 = 0.06,
// b2 = 1.2): an isotropic viscous stress on each cell from its volumetric strain rate eps_v',
//   sigma_bv = b1 rho c_d L_e eps_v' + rho (b2 L_e)^2 eps_v' |eps_v'| (second term in compression only),
// c_d the cell's dilatational wave speed, L_e its smallest edge. It damps the ringing of the
// thickness (dilatational) modes that a sudden load excites, and leaves shear (the loading of the
// contact, the plate's friction) untouched. One-point (cell-average) evaluation: for the box cell
// the mean shape-function gradient is exact for eps_v', and the nodal force f_a = -V sigma_bv
// grad N_a is its work conjugate, so the dissipated power is exactly V sigma_bv eps_v' >= 0.
#include "gradfric/core/exact_sum.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/plate_properties.hpp"

#include <array>
#include <vector>

namespace gradfric::fem {

// Mean gradient of the 8 shape functions over a box cell hx x hy x hz (element node order
// a = i + 2 j + 4 k): d N_a / dx = (2 i - 1) / (4 hx), and likewise in y, z.
std::array<std::array<double, 3>, 8> boxMeanShapeGradients(double hx, double hy, double hz);

// The viscous stress of the formula above for one cell (rate eps_v' [1/s]).
double bulkViscousStress(double linear, double quadratic, double density, double dilatationalSpeed,
                         double length, double volumetricRate);

// The layer (on with b1 or b2 > 0): c_d from each cell's E (plate_properties.hpp).
class BulkViscosity : public Layer {
public:
  BulkViscosity(const PlateMesh& mesh, const PlateProperties& properties, double linear, double quadratic);
  BulkViscosity(const BulkViscosity&) = delete;
  BulkViscosity& operator=(const BulkViscosity&) = delete;

  // The viscous force of the velocities of X into the force slots of F; the energy it takes over
  // the step (power x dt, exact) is added to the work by the post-step.
  const char* name() const override { return "bulk viscosity"; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void postStep(double) override { work_ += step_; }
  LayerWork work() const override;
  void archive(StateArchive& a) override;
  std::string describe() const override;
  void writeProperties(PropertySink& sink) const override;

private:
  double cellForce(PetscInt cell, const PetscScalar* x, std::array<double, 24>* w) const;

  const PlateMesh& mesh_;
  double linear_, quadratic_, density_;
  struct Shape {  // per cell shape (mesh.shapes()): smallest edge, volume, mean shape gradients
    double length, volume;
    std::array<std::array<double, 3>, 8> gradient;
  };
  std::vector<Shape> shapes_;
  std::vector<double> cellSpeed_;  // c_d of each local cell (graded E)
  ExactSum step_, work_;           // this rank's energy of the last right-hand side, and since the start
  OwnedVec xLocal_, fLocal_, fGlobal_;
};

}  // namespace gradfric::fem
