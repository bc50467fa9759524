#pragma once
// The -friction_law options, one reader for both models: the law (-friction_law) and its
// parameters (-friction_v_c, -friction_d_c, and the normal-stress memory -friction_memory_length,
// -friction_memory_speed). Each model passes its own default law, whether it can run laws with a
// per-site state (both models do: the FEM contact, the spring-block reference kernel) and whether
// it has a pressure to remember (the FEM; the spring-block model refuses the memory); a D_c or
// memory length the user sets must not exceed thickness (the plate's H: the law's lengths are
// interface lengths).
#include "gradfric/core/options.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

namespace gradfric {

FrictionLawSettings readFrictionLaw(MPI_Comm comm, RunParameters* record, const FrictionLawSettings& modelDefault,
                                    bool withState, double thickness = 0.0, bool withMemory = false);

}  // namespace gradfric
