#pragma once
// The paper's Eq. 1 (the FEM's law): mu(v) = mu_k + (mu_s - mu_k) exp(-v / v_c). A site at rest
// holds while |F| <= mu_s F_n (Eq. 1 at v = 0); a site sliding at speed v feels mu(v) F_n.
#include "gradfric/physics/friction_law.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

namespace gradfric {

struct ExponentialVelocityWeakening : StaticThreshold {
  static constexpr const char* name = "exponential";
  static constexpr bool weakensWithSpeed = true;

  FrictionSites sites;
  double criticalVelocity = 1e-4;  // v_c > 0 [m/s]

  double slidingStrength(double staticStrength, double kineticStrength, double slipSpeed) const {
    return kineticStrength + (staticStrength - kineticStrength) * std::exp(-slipSpeed / criticalVelocity);
  }
  static std::string describe(const FrictionLawSettings& settings) {
    std::ostringstream text;
    text << "velocity weakening, paper Eq. 1: mu_k + (mu_s - mu_k) exp(-v/v_c), v_c = " << settings.criticalVelocity
         << " m/s";
    return text.str();
  }
  static ExponentialVelocityWeakening make(FrictionSites sites, const FrictionLawSettings& settings) {
    return {{}, std::move(sites), settings.criticalVelocity};
  }
};

}  // namespace gradfric
