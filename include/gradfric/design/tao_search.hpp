#pragma once
// A design with several free parameters: PETSc TAO with a derivative-free method (-design_tao_type
// nm, the default, or pounders; TAO reads its options with the prefix design_), each objective evaluation an ensemble (Evaluator).
//   - TAO runs redundantly on every rank (PETSC_COMM_SELF: a handful of parameters; pounders is
//     serial); it sees the same objective values everywhere, so it takes the same steps, and each
//     objective evaluation is an ensemble collective over the communicator.
//   - TAO sees the parameters scaled to [0, 1] (bounds given with TaoSetVariableBounds); Nelder-
//     Mead, which ignores bounds, is evaluated at the projection with a penalty for the distance.
//   - The objective is ((value - target) / tolerance)^2, the residual (pounders) its root: one
//     unit is the noise level of an evaluation, run to a CI half-width of the tolerance. TAO's
//     absolute tolerance is a quarter of that unit: the search does not chase the noise.
//   - The search stops (TAO_CONVERGED_USER) at the first evaluation that meets the target (inside
//     its CI, CI within the tolerance). TAO stopping otherwise: the closest evaluation, refined,
//     is the design if it meets the target, else the target is reported unreachable (TAO
//     converged) or not converged (TAO ran out of evaluations).
#include "gradfric/design/search.hpp"

#include <mpi.h>

namespace gradfric::design {

inline constexpr const char* kDesignTaoPrefix = "design_";

// Reads and checks TAO's options (-design_tao_type, -design_tao_monitor, ...) before any work, so
// that they count as used and a bad type is refused with exit 2; an unprefixed -tao_* is refused,
// naming its new spelling.
void readDesignTaoOptions();

// Collective over comm.
SearchResult searchWithTao(MPI_Comm comm, DesignModel& evaluator, const Problem& problem, SearchLog& log);

}  // namespace gradfric::design
