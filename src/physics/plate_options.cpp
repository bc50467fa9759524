#include "gradfric/physics/plate_options.hpp"

#include "gradfric/core/input_error.hpp"

#include <petscsys.h>

#include <cmath>
#include <iterator>
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

// Values a plate in a friction experiment can have, in SI units: a value outside is most likely in
// another unit (-plate_E 10 meaning 10 MPa), so it is named, with the unit the option takes
// (docs/running.md, "Physical ranges"). A warning, not a refusal: a model study may want them.
struct PhysicalRange {
  const char* name;
  double low, high;
  const char* unit;
  const char* what;
};
const PhysicalRange kPhysicalRanges[] = {{"L", 1e-6, 10.0, "m", "plates from a micrometre to 10 m"},
                                         {"H", 1e-7, 1.0, "m", "thicknesses from 0.1 um to 1 m"},
                                         {"E", 1e3, 1.2e12, "Pa", "solids from soft gels to diamond"},
                                         {"rho", 10.0, 2.5e4, "kg/m^3", "solids from foams to osmium"},
                                         {"p", 1.0, 1e10, "Pa", "contact pressures up to 10 GPa"},
                                         {"v", 1e-9, 1e3, "m/s", "sliding speeds from 1 nm/s to 1 km/s"}};

void warnOutsidePhysicalRanges(MPI_Comm comm, const OptionReader& o, const Plate& p) {
  const double values[] = {p.length, p.thickness, p.youngsModulus, p.density, p.pressure, p.velocity};
  for (std::size_t k = 0; k < std::size(kPhysicalRanges); ++k) {
    const PhysicalRange& r = kPhysicalRanges[k];
    if (values[k] >= r.low && values[k] <= r.high) continue;
    PetscPrintf(comm, "gradfric: warning: %s = %s %s lies outside %s to %s %s (%s): the option takes SI units (%s)\n",
                o.fullName(r.name).c_str(), formatReal(values[k]).c_str(), r.unit, formatReal(r.low).c_str(),
                formatReal(r.high).c_str(), r.unit, r.what, r.unit);
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
  static bool warned = false;  // the plate is read by each model of a run: one warning per run
  if (!warned && !helpRequested()) warnOutsidePhysicalRanges(comm, o, p);
  warned = true;
  return p;
}

}  // namespace gradfric
