#pragma once
// What a design search returns, and the log of its evaluations (printed as they complete, written
// to the design file at the end). Shared by the root finder and the TAO search.
#include "gradfric/design/evaluator.hpp"

#include <mpi.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::design {

enum class Status {
  Found,         // the target lies in the design's 95 % CI, whose half-width is within the tolerance
  Unreachable,   // the family does not reach the target within the bounds: `design` is the closest
  NotConverged,  // the evaluation budget or the realisation cap ran out first: `design` is the best
  NotVerified,   // found by the search, but the verification ensemble's 95 % CI misses the target
};
const char* toString(Status status);
// The driver's exit status: 0 found, 4 unreachable, 5 not converged, 6 not verified (docs/design.md).
int exitCode(Status status);

struct SearchResult {
  Status status = Status::NotConverged;
  Evaluation design;
  std::string method;  // root, or TAO's type (nm, pounders)
  std::string note;    // how the search ended, in words
  // One parameter: the local slope d value / d x from the bracket around the design (NaN if
  // unknown), and the design's 95 % CI mapped through it onto the parameter.
  double slope = std::numeric_limits<double>::quiet_NaN();
  double parameterLow() const { return design.x[0] - design.halfWidth() / std::fabs(slope); }
  double parameterHigh() const { return design.x[0] + design.halfWidth() / std::fabs(slope); }
};

// The outcome once the design is verified with fresh streams: a found design whose verification's
// CI misses the target becomes NotVerified (the search's CI held it on its own streams only);
// every other outcome, and a run without verification, is the search's.
SearchResult settleOnVerification(SearchResult result, const std::optional<Evaluation>& verification, double target);

class SearchLog {
public:
  SearchLog(MPI_Comm comm, const Problem& problem) : comm_(comm), problem_(problem) {}
  // Records an evaluation (printed on rank 0 with -design_monitor) and returns it.
  const Evaluation& add(const Evaluation& e);
  const std::vector<Evaluation>& all() const { return evaluations_; }
  // Whether e meets the target: inside its CI, and the CI within the tolerance.
  bool meets(const Evaluation& e) const;
  // The evaluation closest to the target (ties: the earliest).
  const Evaluation& closest() const;

private:
  MPI_Comm comm_;
  const Problem& problem_;
  std::vector<Evaluation> evaluations_;
};

}  // namespace gradfric::design
