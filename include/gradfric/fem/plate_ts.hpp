#pragma once
// The TS of a plate model and the boundary between PETSc's callbacks and C++ exceptions.
//  - createPlateTS: the parameters' integrator (gfverlet unless -fem_ts_type says otherwise: the
//    plate's TS reads PETSc's TS options with the prefix fem_), fixed step model.timeStep(),
//    the model's right-hand side, and a post-step that runs the layers' post-step after each
//    accepted step (TSSetPostStep: PETSc calls it from TSSolve only, not from a bare TSStep).
//  - guardedCallback: runs the body of a PETSc callback; an exception becomes a PETSc error code
//    and is kept, and solvePlateTS rethrows it as it was (a NumericalInstability stays one).
#include "gradfric/fem/plate_model.hpp"

#include <petscts.h>

#include <exception>

namespace gradfric::fem {

TS createPlateTS(PlateModel& model, Vec state);

// The options prefix of the plate's TS: -fem_ts_type, -fem_ts_monitor, -fem_ts_view, ...
constexpr const char* kPlateTSPrefix = "fem_";

// Reads the -fem_ts_ options once on a throwaway TS, before any work: an unknown -fem_ts_type,
// a type other than gfverlet with the kinematic contact, and the unprefixed spelling (-ts_type,
// -ts_monitor, ...) are refused early, and the options count as used (checkUnusedOptions runs
// before the model exists).
void readPlateTSOptions(MPI_Comm comm, const FemParameters& params);

// The post-step of createPlateTS (the layers' post-step: contact state, damping work): call it
// first from a post-step that replaces it, then the observers.
PetscErrorCode layersPostStep(TS ts);

// TSSolve(ts, nullptr); rethrows the exception a guarded callback raised, else throws
// PetscCallError on a PETSc error.
void solvePlateTS(TS ts);

namespace detail {
PetscErrorCode keepCallbackError(std::exception_ptr error, const char* what);
}

template <class Body>
PetscErrorCode guardedCallback(Body&& body) {
  try {
    body();
  } catch (const std::exception& e) {
    return detail::keepCallbackError(std::current_exception(), e.what());
  } catch (...) {
    return detail::keepCallbackError(std::current_exception(), "unknown exception");
  }
  return 0;
}

}  // namespace gradfric::fem
