#pragma once
// The -friction_law options, one reader for both models: the law (-friction_law) and its
// parameters (-friction_v_c, -friction_d_c). Each model passes its own default law and whether it
// can run laws with a per-site state (both models do: the FEM contact, the spring-block reference
// kernel); a D_c the user sets must not exceed thickness (the plate's H: the law's length is an
// interface length).
#include "gradfric/core/options.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"

namespace gradfric {

FrictionLawSettings readFrictionLaw(MPI_Comm comm, RunParameters* record, const FrictionLawSettings& modelDefault,
                                    bool withState, double thickness = 0.0);

}  // namespace gradfric
