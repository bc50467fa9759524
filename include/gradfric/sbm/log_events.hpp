#pragma once
// The PETSc log events of the spring-block model (SbmSetup, SbmStep, SbmSnapshot, -log_view):
// routes simulate()'s timing hooks (model.hpp) to PetscLogEventBegin/End. PETSc library.
namespace gradfric::sbm {

// Registers the events once (after PetscInitialize) and installs the hooks; idempotent.
void installLogEvents();

}  // namespace gradfric::sbm
