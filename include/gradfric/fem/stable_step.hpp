#pragma once
// The stable step of the FEM's explicit scheme and the step a run uses.
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

namespace gradfric::fem {

// The stable step for these parameters (no mesh needed: every cell is the same box): element
// frequencies with the stiffest graded E, contact penalty, damping.
double stableTimeStep(const FemParameters& params, const Grading& grading);
// The step a run uses: params.dt if set (refused with the limit in the message if above the
// stable step), else dtSafety * stable step. Throws InputError.
double chooseTimeStep(const FemParameters& params, const Grading& grading);

}  // namespace gradfric::fem
