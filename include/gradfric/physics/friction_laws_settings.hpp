#pragma once
// Which friction law a model uses and the laws' scalar parameters (-friction_law, -friction_v_c,
// -friction_d_c: one reader for both models, friction_law_options.hpp).
#include <string>

namespace gradfric {

struct FrictionLawSettings {
  std::string name = "coulomb";   // one of frictionLawNames() (friction_laws.hpp)
  static constexpr double kCriticalVelocity = 1e-4, kSlipLength = 2.5e-8;  // the defaults of both models
  double criticalVelocity = kCriticalVelocity;  // v_c of the exponential and state laws [m/s]
  double slipLength = kSlipLength;  // D_c of the state law [m] (state_weakening_law.hpp; docs/accuracy_fem.md)
};

}  // namespace gradfric
