#pragma once
// Amontons-Coulomb with distinct static and kinetic coefficients (the SBM's law, the paper's):
// a site at rest holds while |F| <= mu_s F_n; a sliding site feels mu_k F_n whatever its speed.
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

#include <string>
#include <utility>

namespace gradfric {

struct CoulombStickSlip : StaticThreshold {
  static constexpr const char* name = "coulomb";
  static constexpr bool weakensWithSpeed = false;  // the kernels skip the slip speed

  FrictionSites sites;

  double slidingStrength(double /*staticStrength*/, double kineticStrength, double /*slipSpeed*/) const {
    return kineticStrength;
  }
  static std::string describe(const FrictionLawSettings&) {
    return "Amontons-Coulomb stick-slip: static mu_s, kinetic mu_k";
  }
  static CoulombStickSlip make(FrictionSites sites, const FrictionLawSettings&) { return {{}, std::move(sites)}; }
};

}  // namespace gradfric
