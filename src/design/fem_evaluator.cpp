// The FEM as a design's model (include/gradfric/design/fem_evaluator.hpp).
#include "gradfric/design/fem_evaluator.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::design {

namespace {

// A known run serves x when each parameter agrees to 1e-9 relative: a study-table row holds the
// value a search reaches as 0.75 * 0.4, which is not the double 0.3.
bool sameParameters(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::fabs(a[i] - b[i]) > 1e-9 * std::max(1.0, std::fabs(b[i]))) return false;
  return true;
}

}  // namespace

std::array<int, 3> FemEvaluator::mesh() const {
  return {mesh_.parameters.nx, mesh_.parameters.ny, mesh_.parameters.nz};
}

void FemEvaluator::know(const std::vector<KnownFemRun>& runs) {
  for (const KnownFemRun& r : runs) {
    if (r.mesh != mesh()) continue;
    FemRun run;
    run.muStatic = r.muStatic;
    run.peakConfirmed = true;  // only confirmed runs are recorded
    run.flutter = r.flutter;
    run.reused = true;
    if (r.reference) {
      if (!reference_) reference_ = Known{run};
    } else {
      runsAt_.emplace(r.x, Known{run});
    }
  }
}

FemRun& FemEvaluator::at(const std::vector<double>& x) {
  auto it = runsAt_.find(x);
  if (it == runsAt_.end())
    for (auto k = runsAt_.begin(); k != runsAt_.end(); ++k)
      if (k->second.run.reused && sameParameters(x, k->first)) {
        it = k;
        break;
      }
  if (it == runsAt_.end()) {
    it = runsAt_.emplace(x, Known{runFemPlate(comm_, mesh_, problem_.gradingAt(x))}).first;
    ++runs_;
  }
  if (it->second.run.reused && !it->second.taken) ++reused_, it->second.taken = true;
  return it->second.run;
}

FemRun& FemEvaluator::reference() {
  if (!reference_) {
    reference_ = Known{runFemPlate(comm_, mesh_, problem_.referenceGrading())};
    ++runs_;
  }
  if (reference_->run.reused && !reference_->taken) ++reused_, reference_->taken = true;
  return reference_->run;
}

FemVerification FemEvaluator::check(const std::vector<double>& x) {
  FemVerification v;
  v.design = at(x);
  if (problem_.kind == TargetKind::Variation) v.reference = reference();
  v.cells = mesh_.parameters.nx * mesh_.parameters.ny * mesh_.parameters.nz;
  return v;
}

Evaluation FemEvaluator::evaluate(const std::vector<double>& x, double, const std::string& phase, std::uint32_t, int) {
  const FemRun& r = at(x);
  // Every rank ran the same run: the same decision everywhere.
  const auto confirmed = [](const FemRun& run, const std::string& what) {
    if (!run.peakConfirmed)
      throw CollectiveError("the FEM run at " + what + " did not confirm its static peak (mu_s " +
                            formatReal(run.muStatic) + "): lengthen it (-fem_slide_time) or check the plate");
  };
  confirmed(r, problem_.describe(x));
  const bool variation = problem_.kind == TargetKind::Variation;
  if (variation) confirmed(reference(), "the non-graded plate");
  Evaluation e;
  e.phase = phase;
  e.x = x;
  e.realisations = 1;
  e.exact = true;
  e.acceptance = acceptance_;
  e.muStatic = e.muStaticCiLow = e.muStaticCiHigh = r.muStatic;
  e.value = variation ? r.muStatic / reference().muStatic - 1.0 : r.muStatic;
  e.flutter = r.flutter;
  e.femMesh = mesh();
  e.reused = r.reused;
  if (variation) e.femReference = reference().muStatic;
  e.ciLow = e.ciHigh = e.value;
  return e;
}

}  // namespace gradfric::design
