#pragma once
// The FEM's PETSc log events (-log_view): the right-hand side and its parts.
#include <petsclog.h>

namespace gradfric::fem {

struct FemLogEvents {
  PetscLogEvent rhs = 0, elastic = 0, contact = 0, generic = 0;
};

// Registered once per process, on first use (after PetscInitialize).
const FemLogEvents& femLogEvents();

}  // namespace gradfric::fem
