#pragma once
// One error term from one ladder of the FEM study's rows (three meshes or steps at ratio 2), by the
// rule both models share (core/refinement_ladder.hpp), with the text that says what it rests on.
// PETSc-free.
#include "gradfric/fem/error_estimate.hpp"
#include "gradfric/fem/study_table.hpp"

#include <string>

namespace gradfric::fem {

// The bound of one member of the ladder m (coarse, medium, fine; member 0, 1 or 2), or none where
// the ladder does not converge. term, ladder: the names in the basis ("mesh", "50x50x5/...").
ErrorTerm ladderTerm(const char* term, const std::string& ladder, const StudyRow* const m[3], int member);

// A member whose own ladder (own, not measured) does not converge, bounded through the finest value
// of the finer ladders, which all converge (core boundThroughFinerValue): |value - limit| <=
// |value - finestValue| + finest's bound.
ErrorTerm throughFinerValue(const char* term, const ErrorTerm& own, double value, const ErrorTerm& finest,
                            double finestValue);

}  // namespace gradfric::fem
