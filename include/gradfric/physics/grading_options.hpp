#pragma once
// The -grading_ options, shared by every model so that a scene grades SBM and FEM alike.
#include "gradfric/core/options.hpp"
#include "gradfric/physics/grading.hpp"

namespace gradfric {

// Reads and validates -grading_profile, -grading_property, -grading_delta, -grading_bands.
Grading readGrading(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric
