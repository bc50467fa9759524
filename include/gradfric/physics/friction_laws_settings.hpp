#pragma once
// Which friction law a model uses and the laws' scalar parameters (-friction_law, -friction_v_c,
// -friction_d_c, -friction_memory_length, -friction_memory_speed: one reader for both models,
// friction_law_options.hpp).
#include <string>

namespace gradfric {

struct FrictionLawSettings {
  std::string name = "coulomb";   // one of frictionLawNames() (friction_laws.hpp)
  static constexpr double kCriticalVelocity = 1e-4, kSlipLength = 2.5e-8;  // the defaults of both models
  static constexpr double kMemorySpeed = 0.01;  // V* of the normal-stress memory [m/s]
  double criticalVelocity = kCriticalVelocity;  // v_c of the exponential and state laws [m/s]
  double slipLength = kSlipLength;  // D_c of the state law [m] (state_weakening_law.hpp; docs/accuracy_fem.md)
  // The normal-stress memory of the state law (normal_stress_memory.hpp): its slip length
  // L_sigma in units of D_c (0: none, the strength multiplies the pressure of the moment) and its
  // reference speed V* [m/s].
  double memoryLength = 0.0;
  double memorySpeed = kMemorySpeed;

  double memoryLengthInMetres() const { return memoryLength * slipLength; }
};

}  // namespace gradfric
