// The FEM as a design's model (include/gradfric/design/fem_evaluator.hpp).
#include "gradfric/design/fem_evaluator.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/design/fem_check.hpp"

namespace gradfric::design {

FemEvaluator::Run FemEvaluator::run(const Grading& grading, const std::string& what) {
  const FemVerification r = runFemCheck(comm_, mesh_, grading);
  ++runs_;
  if (!r.peakConfirmed)  // every rank ran the same run: the same decision everywhere
    throw CollectiveError("the FEM run at " + what + " did not confirm its static peak (mu_s " + formatReal(r.muStatic) +
                          "): lengthen it (-fem_slide_time) or check the plate");
  return {r.muStatic, r.flutter};
}

std::array<int, 3> FemEvaluator::mesh() const {
  return {mesh_.parameters.nx, mesh_.parameters.ny, mesh_.parameters.nz};
}

void FemEvaluator::know(const std::vector<KnownFemRun>& runs) {
  for (const KnownFemRun& r : runs) {
    if (r.mesh != mesh()) continue;
    if (r.reference) {
      if (!reference_) reference_ = r.muStatic, referenceKnown_ = true;
    } else {
      runsAt_.emplace(r.x, Run{r.muStatic, r.flutter, true});
    }
  }
}

Evaluation FemEvaluator::evaluate(const std::vector<double>& x, double, const std::string& phase, std::uint32_t, int) {
  auto known = runsAt_.find(x);
  if (known == runsAt_.end()) known = runsAt_.emplace(x, run(problem_.gradingAt(x), problem_.describe(x))).first;
  const bool reused = known->second.known;
  if (reused) ++reused_, known->second.known = false;  // counted once
  const bool variation = problem_.kind == TargetKind::Variation;
  if (variation && !reference_) reference_ = run(problem_.referenceGrading(), "the non-graded plate").muStatic;
  if (variation && referenceKnown_) ++reused_, referenceKnown_ = false;
  Evaluation e;
  e.phase = phase;
  e.x = x;
  e.realisations = 1;
  e.exact = true;
  e.acceptance = acceptance_;
  const Run& r = known->second;
  e.muStatic = e.muStaticCiLow = e.muStaticCiHigh = r.muStatic;
  e.value = variation ? r.muStatic / *reference_ - 1.0 : r.muStatic;
  e.flutter = r.flutter;
  e.femMesh = mesh();
  e.reused = reused;
  if (variation) e.femReference = *reference_;
  e.ciLow = e.ciHigh = e.value;
  return e;
}

}  // namespace gradfric::design
