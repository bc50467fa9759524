#pragma once
// The second mesh family as a check and a bound of the first (docs/accuracy_fem.md, "The second
// family checks the first"). The uniform meshes and the meshes graded toward the edges discretise
// one problem, so their converging ladders share its limit:
//  - bounded through: a uniform run whose own ladders prove no bound is bounded through the finest
//    value of a converging graded ladder whose finest mesh is nowhere coarser than the run's,
//    |mu - mu_lim| <= |mu - mu_f| + |mu_f - mu_lim| (core boundThroughFinerValue);
//  - refuted by: a bound from the run's own family is withdrawn where a converging graded ladder
//    bounds a limit that bound does not reach (core shareALimit).
// PETSc-free.
#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/fem/study_table.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

// A ladder refined in every direction on meshes graded toward the edges: its finest row and that
// row's bound (not measured where the ladder does not converge; its basis then says why).
struct GradedLadder {
  const StudyRow* finest = nullptr;
  ErrorTerm term;
};

// Every graded ladder of the run's plate refined in every direction (the finest ladder of each edge
// grading the study has), at the run's filter, converging or not.
std::vector<GradedLadder> edgeGradedLadders(const std::vector<StudyRow>& rows, const FemParameters& q,
                                            const Grading& g);

// The run (its study row) bounded through the converging graded ladder that gives the smallest
// bound, or not measured where none is nowhere coarser than its mesh.
ErrorTerm throughEdgeGradedLadder(const StudyRow& run, const std::vector<GradedLadder>& ladders,
                                  const FemParameters& q);

// The refutation of the run's own bound `mesh` by the first converging graded ladder whose bound
// shares no limit with it, or "" where none.
std::string refutedByEdgeGradedLadder(const StudyRow& run, const std::vector<GradedLadder>& ladders,
                                      const ErrorTerm& mesh);

}  // namespace gradfric::fem
