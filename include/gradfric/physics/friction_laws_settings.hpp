#pragma once
// Which friction law a model uses and the laws' scalar parameters (-sbm_friction_law, -sbm_v_c).
#include <string>

namespace gradfric {

struct FrictionLawSettings {
  std::string name = "coulomb";   // one of frictionLawNames() (friction_laws.hpp)
  double criticalVelocity = 1e-4;  // v_c of the exponential law [m/s] (the FEM's default)
};

}  // namespace gradfric
