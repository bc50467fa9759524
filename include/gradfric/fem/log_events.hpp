#pragma once
// The FEM's PETSc log events (-log_view): the right-hand side and its parts.
#include "gradfric/core/log_event.hpp"

namespace gradfric::fem {

struct FemLogEvents {
  PetscLogEvent rhs = 0, elastic = 0, contact = 0, generic = 0;
  PetscLogEvent postStep = 0, monitor = 0;  // per-step work outside the right-hand side
  PetscLogEvent output = 0;                 // snapshots of the fields
};

// Registered once per process, on first use (after PetscInitialize).
const FemLogEvents& femLogEvents();

}  // namespace gradfric::fem
