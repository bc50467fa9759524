#pragma once
// The stable step of the FEM's explicit scheme and the step a run uses.
#include "gradfric/core/options.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

namespace gradfric::fem {

// The stable step for these parameters (no mesh needed: the cells' boxes follow from the options):
// element frequencies with the stiffest graded E (on an edge-graded mesh, each cell shape with the
// stiffest E among its cells), contact penalty, damping.
// The default step is dt_safety times this.
double stableTimeStep(const FemParameters& params, const Grading& grading);
// The largest step accepted: the same with the coupling of a sliding node's friction force to its
// normal penalty spring (k_n sqrt(1 + mu_s^2) in place of k_n, mu_s the largest local value).
double largestTimeStep(const FemParameters& params, const Grading& grading);
// The step a run uses, by the shared TimeStepPolicy (physics/stability.hpp): params.dt if set
// (refused above largestTimeStep unless -fem_dt_check false), else dtSafety * stable step
// (-fem_dt_safety refused when that is above largestTimeStep). Throws InputError.
double chooseTimeStep(const FemParameters& params, const Grading& grading);
// Refuses, before any work, a run of more than 1e9 steps (pressure step + sliding at the chosen
// dt), naming the option the user set that made it so (see core/run_limits.hpp).
void requireFemRunLength(const FemParameters& params, const Grading& grading, const RunParameters* record);

}  // namespace gradfric::fem
