#pragma once
// Reading the FEM's parameters from PETSc options (-fem_*), with validation before any work.
// Part of the PETSc library (the structs are in parameters.hpp, in the core).
#include "gradfric/core/options.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/plate.hpp"

namespace gradfric::fem {

// Reads and validates every -fem_ option (derived defaults recorded as such).
FemParameters readFemParameters(MPI_Comm comm, RunParameters* record, const Plate& plate);

}  // namespace gradfric::fem
