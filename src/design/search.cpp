// The log and result of a design search (include/gradfric/design/search.hpp).
#include "gradfric/design/search.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <cmath>
#include <stdexcept>

namespace gradfric::design {

const char* toString(Status status) {
  switch (status) {
    case Status::Found: return "found";
    case Status::Unreachable: return "unreachable";
    case Status::NotVerified: return "not_verified";
    default: return "not_converged";
  }
}

int exitCode(Status status) {
  switch (status) {
    case Status::Found: return 0;
    case Status::Unreachable: return 4;
    case Status::NotVerified: return 6;
    default: return 5;
  }
}

SearchResult settleOnVerification(SearchResult result, const std::optional<Evaluation>& verification, double target) {
  if (result.status != Status::Found || !verification || verification->side(target) == 0) return result;
  result.status = Status::NotVerified;
  result.note = "the search held the target in its CI, but the verification's CI (fresh streams) misses it: "
                "the design's interval understates its uncertainty here (more realisations: a smaller "
                "-design_tolerance)";
  return result;
}

const Evaluation& SearchLog::add(const Evaluation& evaluation) {
  evaluations_.push_back(evaluation);
  Evaluation& e = evaluations_.back();
  e.index = static_cast<int>(evaluations_.size()) - 1;  // one order over every model and mesh
  if (problem_.monitor) {
    const char* where = e.side(problem_.target) == 0 ? "target inside" : e.side(problem_.target) > 0 ? "above target" : "below target";
    GF_CALL(PetscPrintf(comm_, "  eval %2d %-8s %s: R = %3d, %s = %.6f, 95%% CI [%.6f, %.6f] (+- %.6f), %s\n", e.index,
                        e.phase.c_str(), problem_.describe(e.x).c_str(), e.realisations,
                        problem_.kind == TargetKind::Variation ? "variation" : "mu_s", e.value, e.ciLow, e.ciHigh,
                        e.halfWidth(), where));
  }
  return evaluations_.back();
}

bool SearchLog::meets(const Evaluation& e) const {
  return e.side(problem_.target) == 0 && e.halfWidth() <= problem_.tolerance * (1.0 + 1e-12);
}

const Evaluation& SearchLog::closest() const {
  if (evaluations_.empty()) throw std::logic_error("design search without evaluations");
  const Evaluation* best = &evaluations_.front();
  for (const auto& e : evaluations_)
    if (std::fabs(e.value - problem_.target) < std::fabs(best->value - problem_.target)) best = &e;
  return *best;
}

}  // namespace gradfric::design
