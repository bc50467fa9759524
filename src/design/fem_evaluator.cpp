// The FEM as a design's model (include/gradfric/design/fem_evaluator.hpp).
#include "gradfric/design/fem_evaluator.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/design/fem_check.hpp"

namespace gradfric::design {

double FemEvaluator::run(const Grading& grading, const std::string& what) {
  const FemVerification r = runFemCheck(comm_, mesh_, grading);
  ++runs_;
  if (!r.peakConfirmed)  // every rank ran the same run: the same decision everywhere
    throw CollectiveError("the FEM run at " + what + " did not confirm its static peak (mu_s " + formatReal(r.muStatic) +
                          "): lengthen it (-fem_slide_time) or check the plate");
  return r.muStatic;
}

Evaluation FemEvaluator::evaluate(const std::vector<double>& x, double, const std::string& phase, std::uint32_t, int) {
  auto known = muStatic_.find(x);
  if (known == muStatic_.end()) known = muStatic_.emplace(x, run(problem_.gradingAt(x), problem_.describe(x))).first;
  const bool variation = problem_.kind == TargetKind::Variation;
  if (variation && !reference_) reference_ = run(problem_.referenceGrading(), "the non-graded plate");
  Evaluation e;
  e.phase = phase;
  e.x = x;
  e.realisations = 1;
  e.exact = true;
  e.acceptance = acceptance_;
  e.muStatic = e.muStaticCiLow = e.muStaticCiHigh = known->second;
  e.value = variation ? known->second / *reference_ - 1.0 : known->second;
  e.ciLow = e.ciHigh = e.value;
  return e;
}

}  // namespace gradfric::design
