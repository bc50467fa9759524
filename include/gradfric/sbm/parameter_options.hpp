#pragma once
// Reading the spring-block parameters and the observables from PETSc options (-sbm_*), with
// validation before any work. Part of the PETSc library (the structs are in parameters.hpp).
#include "gradfric/core/options.hpp"
#include "gradfric/physics/friction_options.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/sbm/parameters.hpp"

namespace gradfric::sbm {

// Reads -sbm_* (physics, numerics) and the observable options; validates before any work.
// The grading is needed for the stability limit (the stiffest band). Also routes simulate()'s
// timing hooks to the PETSc log events GfSbmSetup, GfSbmStep, GfSbmSnapshot (-log_view).
Parameters readParameters(MPI_Comm comm, RunParameters* record, const Plate& plate, const Grading& grading);
// defaults: the caller's measurement defaults (a calibration: mu_s only), which the options override.
Request readRequest(MPI_Comm comm, RunParameters* record, const Parameters& parameters,
                    const MeasurementDefaults& defaults = {});

}  // namespace gradfric::sbm
