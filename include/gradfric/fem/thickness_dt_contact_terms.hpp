#pragma once
// The terms of the FEM's mu_s error bar besides the in-plane mesh, each from a ladder of the study's
// rows (docs/fem_study.tsv; docs/accuracy_fem.md, "Convergence of mu_s"), by the rule the mesh term
// uses (ladder_term.hpp):
//  - thickness: the ladder nz 5/10/20 of the run's plate and in-plane mesh, else of the non-graded
//    plate at that mesh, else at 100 x 100; every finer in-plane mesh's ladder must converge too;
//  - time step: the ladder dt_safety 0.6/0.3/0.15 of the non-graded 100 x 100 x 5 plate (the bound
//    of 0.6 covers smaller steps);
//  - contact: penalty 250 G/H against the kinematic contact (the exact reference, no refinement) on
//    the same plate, 1.25 |difference|.
// A filtered run takes the rungs with its Prakash-Clifton filter where the study has them all, else
// those without (ErrorTerm::filtered says which). PETSc-free.
#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/fem/study_table.hpp"

#include <vector>

namespace gradfric::fem {

ErrorTerm thicknessTerm(const std::vector<StudyRow>& rows, const FemParameters& q, const Grading& g);

// dtRatio: the run's dt / stable step.
ErrorTerm timeStepTerm(const std::vector<StudyRow>& rows, const FemParameters& q, double dtRatio);

ErrorTerm contactTerm(const std::vector<StudyRow>& rows, const FemParameters& q);

}  // namespace gradfric::fem
