#pragma once
// The PETSc log events of the spring-block model (GfSbmSetup, GfSbmStep, GfSbmSnapshot, -log_view):
// routes simulate()'s timing hooks (model.hpp) to PetscLogEventBegin/End. PETSc library.
namespace gradfric::sbm {

// Registers the events once (after PetscInitialize) and installs the hooks; idempotent.
void installLogEvents();

}  // namespace gradfric::sbm
