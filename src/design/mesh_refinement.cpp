// The coarse-to-fine FEM design (include/gradfric/design/mesh_refinement.hpp).
#include "gradfric/design/mesh_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::design {

SearchResult refineOnFineMesh(DesignModel& fine, const Problem& problem, SearchLog& log, const SearchResult& coarse) {
  const std::string mesh = std::to_string(problem.coarseFem->parameters.nx) + "x" +
                           std::to_string(problem.coarseFem->parameters.ny) + "x" +
                           std::to_string(problem.coarseFem->parameters.nz);
  if (coarse.status != Status::Found) {
    SearchResult out = coarse;
    out.note = "on the coarse mesh " + mesh + ": " + coarse.note + " (not run on the -fem_* mesh)";
    return out;
  }
  const FreeParameter& f = problem.free[0];
  double slope = coarse.slope;
  std::vector<double> x = coarse.design.x;
  Evaluation e = log.add(fine.evaluate(x, problem.tolerance, "fine"));
  for (int k = 1; !log.meets(e) && k < problem.fineEvaluations; ++k) {
    if (!(std::isfinite(slope) && slope != 0.0)) break;
    const std::vector<double> next{std::clamp(x[0] - (e.value - problem.target) / slope, f.lower, f.upper)};
    if (next[0] == x[0]) break;  // pinned at a bound
    const Evaluation n = log.add(fine.evaluate(next, problem.tolerance, "fine"));
    const double secant = (n.value - e.value) / (next[0] - x[0]);
    if (std::isfinite(secant) && secant * slope > 0) slope = secant;  // the fine mesh's own, if it keeps the sign
    x = next;
    e = n;
  }
  SearchResult out;
  out.method = coarse.method;
  out.design = e;
  out.slope = slope;
  const int runs = static_cast<int>(std::count_if(log.all().begin(), log.all().end(),
                                                  [](const Evaluation& v) { return v.phase == "fine"; }));
  if (log.meets(e)) {
    out.status = Status::Found;
    out.note = "found on the coarse mesh " + mesh + ", confirmed on the -fem_* mesh in " + std::to_string(runs) + " run(s)";
  } else {
    out.status = Status::NotConverged;
    out.note = "found on the coarse mesh " + mesh + "; on the -fem_* mesh " + std::to_string(runs) +
               " run(s) (-design_fine_evaluations) did not reach the tolerance: the design is the last";
  }
  return out;
}

}  // namespace gradfric::design
