#include "gradfric/physics/plate.hpp"

#include "gradfric/core/data_table.hpp"

#include <cstdio>

namespace gradfric {

std::string differenceFromPapersPlate(const Plate& plate, PlateThickness thickness) {
  const Plate paper;
  struct Field {
    const char* name;  // as the option's help names it, with its unit
    double value, papers;
  };
  const Field fields[] = {{"L [m]", plate.length, paper.length},
                          {"H [m]", thickness == PlateThickness::Compared ? plate.thickness : paper.thickness,
                           paper.thickness},
                          {"E0 [Pa]", plate.youngsModulus, paper.youngsModulus},
                          {"nu", plate.poissonRatio, paper.poissonRatio},
                          {"rho [kg/m^3]", plate.density, paper.density},
                          {"p [Pa]", plate.pressure, paper.pressure},
                          {"v [m/s]", plate.velocity, paper.velocity},
                          {"mu_s", plate.muStatic, paper.muStatic},
                          {"mu_k", plate.muKinetic, paper.muKinetic}};
  for (const Field& f : fields) {
    if (sameStudiedValue(f.value, f.papers)) continue;
    char text[160];
    std::snprintf(text, sizeof text, "plate other than the paper's (%s %g, the paper's %g)", f.name, f.value, f.papers);
    return text;
  }
  return "";
}

}  // namespace gradfric
