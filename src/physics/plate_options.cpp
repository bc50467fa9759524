#include "gradfric/physics/plate_options.hpp"

#include "gradfric/core/input_error.hpp"

#include <petscsys.h>

#include <cmath>
#include <string>

namespace gradfric {

namespace {

const char* const kPlateNames[] = {"L", "H", "E", "nu", "rho", "p", "v", "theta", "mu_s", "mu_k"};

// A scene written before the plate record existed: name the new spelling instead of running
// with a silently ignored value.
void refuseOldNames() {
  for (const char* model : {"sbm_", "fem_"}) {
    for (const char* name : kPlateNames)
      refuseRenamedOption(std::string("-") + model + name, std::string("-plate_") + name,
                          "the plate's properties are shared by both models");
  }
}

}  // namespace

Plate readPlate(MPI_Comm comm, RunParameters* record) {
  refuseOldNames();
  OptionReader o(comm, "plate_", "Plate (both models; paper, System parameters)", record);
  Plate p;
  p.length = o.real("L", p.length, "m", "side L of the square plate");
  p.thickness = o.real("H", p.thickness, "m", "thickness H (FEM mesh; Eq. 2); the SBM's mass layer is -sbm_lz");
  p.youngsModulus = o.real("E", p.youngsModulus, "Pa", "reference Young's modulus E0 (graded by -grading_*)");
  p.poissonRatio = o.real("nu", p.poissonRatio, "1", "Poisson's ratio (the SBM lattice requires 1/3)");
  p.density = o.real("rho", p.density, "kg/m^3", "density rho");
  p.pressure = o.real("p", p.pressure, "Pa", "normal pressure p on the top face (total normal force p L^2)");
  p.velocity = o.real("v", p.velocity, "m/s", "sliding speed v of the top face (FEM) or slider (SBM)");
  p.slidingAngle = o.real("theta", p.slidingAngle, "degree", "angle between the sliding direction and the grading axis x");
  p.muStatic = o.real("mu_s", p.muStatic, "1", "mean local static friction coefficient mu_s (graded by -grading_*)");
  p.muKinetic = o.real("mu_k", p.muKinetic, "1", "mean local kinetic friction coefficient mu_k");

  o.requirePositive("L", p.length, "m");
  o.requirePositive("H", p.thickness, "m");
  if (!(p.thickness < p.length))
    throw InputError(o.fullName("H"), formatReal(p.thickness), "0 < H < L = " + formatReal(p.length) + " m (a plate)");
  o.requirePositive("E", p.youngsModulus, "Pa");
  o.requireRange("nu", p.poissonRatio, 0.0, 0.4999, "0 <= nu < 0.5");
  o.requirePositive("rho", p.density, "kg/m^3");
  o.requirePositive("p", p.pressure, "Pa");
  o.requirePositive("v", p.velocity, "m/s");
  if (!std::isfinite(p.slidingAngle) || std::fabs(p.slidingAngle) > 360.0)
    throw InputError(o.fullName("theta"), formatReal(p.slidingAngle), "-360 <= theta <= 360 [degree]");
  o.requirePositive("mu_s", p.muStatic, "");
  o.requirePositive("mu_k", p.muKinetic, "");
  if (!(p.muKinetic <= p.muStatic))
    throw InputError(o.fullName("mu_k"), formatReal(p.muKinetic), "0 < mu_k <= mu_s = " + formatReal(p.muStatic));
  return p;
}

}  // namespace gradfric
