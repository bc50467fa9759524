#pragma once
// What the mu_k study (docs/fem_study_kinetic.tsv; docs/accuracy_fem.md, "mu_k") says of a run's
// mu_k, printed beside it. Full runs through the kinetic window are expensive, so the study is the
// non-graded plate refined in every direction. Its rungs are window means, so the ladder is judged
// as a statistical one (core/refinement_ladder.hpp): each window's batch-mean range gives the rung a
// standard error. No bar is printed: even a converging mesh ladder leaves the time step and the
// contact of mu_k unstudied. For the non-graded plate the exact steady value is known (the state
// law's steady state, Eq. 1 at the sliding speed), and each rung's offset from it is reported.
// PETSc-free.
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <string>

namespace gradfric::fem {

// Why the run's mu_k carries no bar, with what the study measured on its mesh ladder.
// kineticTable: the text of a mu_k study table (the embedded docs/fem_study_kinetic.tsv by default).
// dtRatio: dt / stable step of the run (the study's rungs ran at dt_safety 0.6).
std::string kineticErrorBasis(const FemParameters& params, const Grading& grading, double dtRatio);
std::string kineticErrorBasis(const FemParameters& params, const Grading& grading, double dtRatio,
                              const std::string& kineticTable);

// The standard error of a window mean from the range of its kSteadyBatches batch means (relative
// spread times |mean|): range / (d2 sqrt(n)), d2 = 2.059 the expected range of 4 normal samples.
double windowStandardError(double mean, double spread);

}  // namespace gradfric::fem
