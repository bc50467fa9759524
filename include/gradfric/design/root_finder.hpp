#pragma once
// The stochastic root finder of a one-parameter design (docs/design.md): find x in [lower, upper]
// whose ensemble mean of the target's quantity equals the target.
//   1. Bracket: evaluate both bounds at the coarse precision; if the target is not between them,
//      try up to -design_scan_points interior points (midpoint, then quarters, ...) for a sign
//      change; none: the target is unreachable, reported with the closest attainable value.
//   2. Regula falsi (Illinois) steps on the ensemble means inside the bracket, each evaluation at a
//      precision between the coarse one and the tolerance (half the smaller distance of the
//      bracket's ends to the target): coarse far from the target, the tolerance near it.
//   3. An evaluation whose CI holds the target is refined to the tolerance; the search stops when
//      the target lies in the CI and the CI's half-width is within the tolerance.
// A side is decided only by a CI that excludes the target: noise cannot flip the bracket.
#include "gradfric/design/search.hpp"

#include <functional>

namespace gradfric::design {

// An evaluation at x to a CI half-width (Evaluator::evaluate on stream 0, or a stand-in in tests).
using EvaluateFunction = std::function<Evaluation(const std::vector<double>& x, double halfWidth, const std::string& phase)>;

// Collective (through the evaluations).
SearchResult findRoot(const EvaluateFunction& evaluate, const Problem& problem, SearchLog& log);
SearchResult findRoot(DesignModel& model, const Problem& problem, SearchLog& log);

}  // namespace gradfric::design
