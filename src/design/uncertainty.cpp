// The design's uncertainty, source by source (include/gradfric/design/uncertainty.hpp).
#include "gradfric/design/uncertainty.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/study/scene_key.hpp"

#include <algorithm>

namespace gradfric::design {

study::StudyBar designStudyBar(const Problem& problem, const RunParameters& record, const std::vector<double>& x) {
  for (const FreeParameter& f : problem.free)
    if (f.name != "grading_delta") {
      study::StudyBar bar;
      bar.why = "the free parameter " + f.name + " is a field's, whose design point the study tables are not searched for";
      return bar;
    }
  const bool fem = problem.model == "fem";
  const study::SceneKey key = designRunScene(problem, record, problem.gradingAt(x), fem);
  const std::string table = fem ? "fem_study.tsv" : "sbm_study.tsv";
  const std::vector<int> mesh = fem ? std::vector<int>{problem.fem->parameters.nx, problem.fem->parameters.ny,
                                                       problem.fem->parameters.nz}
                                    : std::vector<int>{problem.parameters.blocksPerSide};
  if (problem.kind == TargetKind::Variation)  // the ladder of mu_s / mu_s,0 - 1 against the non-graded plate
    return study::variationBar(table, "mu_s", key, designRunScene(problem, record, problem.referenceGrading(), fem), mesh);
  return study::studyBar(table, "mu_s", key, mesh);
}

study::SceneKey designRunScene(const Problem& problem, const RunParameters& record, const Grading& g, bool fem) {
  campaign::SweepPoint point;
  point.delta = g.delta;
  point.property = toString(g.property);
  point.profile = toString(g.profile);
  point.theta = problem.parameters.plate.slidingAngle;
  point.sigma = problem.parameters.surface.sigmaStatic;
  point.sigmaKinetic = problem.parameters.surface.sigmaKinetic;
  study::SceneKey key = study::sceneKey(record, {"-sbm_N"}, &point);
  // The design's own options choose where to look, not what a run computes; in the FEM, the
  // spring blocks' options do not enter its run, and its own (-fem_*) come from its record.
  key.erase(std::remove_if(key.begin(), key.end(),
                           [&](const auto& kv) {
                             return kv.first.rfind("design_", 0) == 0 ||
                                    (fem && (kv.first.rfind("sbm_", 0) == 0 || kv.first.rfind("surface_", 0) == 0));
                           }),
            key.end());
  if (!fem) return key;
  for (const auto& kv : study::sceneKey(problem.fem->record, {"-fem_nx", "-fem_ny", "-fem_nz"}))
    if (kv.first.rfind("fem_", 0) == 0 || kv.first.rfind("surface_", 0) == 0) key.push_back(kv);
  std::sort(key.begin(), key.end());
  return key;
}

double femTargetValue(const Problem& problem, const FemVerification& fem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!fem.design.peakConfirmed) return nan;
  if (problem.kind == TargetKind::Absolute) return fem.design.muStatic;
  if (!fem.reference || !fem.reference->peakConfirmed || !(fem.reference->muStatic > 0)) return nan;
  return fem.design.muStatic / fem.reference->muStatic - 1.0;
}

DesignUncertainty designUncertainty(const Problem& problem, const SearchResult& result, double otherValue,
                                    const study::StudyBar& bar, const std::vector<Evaluation>& variants,
                                    const Evaluation* reference) {
  DesignUncertainty u;
  const Evaluation& d = result.design;
  const bool slope = problem.dimension() == 1 && std::isfinite(result.slope) && result.slope != 0.0;
  const double x = d.x[0];
  double statistical = 0.0, discretisation = 0.0;
  if (slope) {
    statistical = d.halfWidth() / std::fabs(result.slope);
    u.statistical = {x - statistical, x + statistical};
  }

  const bool fem = problem.model == "fem";
  const std::string other = fem ? "the spring blocks" : "the FEM";
  // Discretisation: the study's bar of the target's quantity (mu_s, or the variation's ladder).
  const char* quantity = problem.kind == TargetKind::Variation ? "the variation" : "mu_s";
  if (!bar.measured || !bar.verdict.bounded())
    u.discretisationNote = "not measured: " + (bar.why.empty() ? std::string("the ladder shows no convergence") : bar.why);
  else if (!slope)
    u.discretisationNote = "+- " + formatNumber("%.3g", bar.verdict.uncertainty) + " on " + quantity +
                           " (no slope to map it: several parameters)";
  else {
    discretisation = bar.verdict.uncertainty / std::fabs(result.slope);
    u.discretisation = {x - discretisation, x + discretisation};
    u.discretisationNote = "+- " + formatNumber("%.3g", bar.verdict.uncertainty) + " on " + quantity + ", " +
                           (fem ? "the FEM's" : "the spring blocks'") + " study bar";
  }

  // Model form: where the other model would reach the design's value, at the design model's slope.
  u.otherValue = otherValue;
  if (!fem && !problem.fem)
    u.modelFormNote = std::string("not measured: run with -design_verify_fem (one FEM run at the design") +
                      (problem.kind == TargetKind::Variation ? " and one of the non-graded plate)" : ")");
  else if (!std::isfinite(otherValue))
    u.modelFormNote = "not measured: " + other + " did not confirm its peak";
  if (std::isfinite(otherValue)) {
    const double gap = otherValue - d.value;
    u.modelFormNote = other + " at the design: " + formatNumber("%.6f", otherValue) + " against " +
                      (fem ? std::string("the FEM's ") : std::string("the spring blocks' ")) + formatNumber("%.6f", d.value) +
                      " (" + formatNumber("%+.6f", gap) + ")";
    if (slope) {
      const double otherX = x - gap / result.slope;
      u.modelForm = {std::min(x, otherX), std::max(x, otherX)};
      u.modelFormNote += "; at " + (fem ? std::string("the FEM's") : std::string("the spring blocks'")) + " slope " +
                         other + (fem ? " reach" : " reaches") + " it at " + formatNumber("%.6g", otherX);
    }
  }

  // Variants: where each reaches the reference's value at the design model's slope, with its CI.
  if (problem.variants.empty())
    u.variantsNote = "not measured: no -design_variants";
  else {
    const Evaluation& ref = reference ? *reference : d;
    u.variantLines.push_back("against the " + std::string(reference ? "verification's " : "design's ") +
                             formatNumber("%.6f", ref.value) + ":");
    if (slope) u.variants = {x, x};
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const Evaluation& v = variants[k];
      std::string line = problem.variants[k].file + " (" + problem.variants[k].options + ") " +
                         formatNumber("%.6f", v.value) + " [" + formatNumber("%.6f", v.ciLow) + ", " +
                         formatNumber("%.6f", v.ciHigh) + "] (" + formatNumber("%+.6f", v.value - ref.value) + ")";
      double reach = std::numeric_limits<double>::quiet_NaN();
      if (slope) {
        reach = x - (v.value - ref.value) / result.slope;
        const double spread = v.halfWidth() / std::fabs(result.slope);
        u.variants = {std::min(u.variants.low, reach - spread), std::max(u.variants.high, reach + spread)};
        line += ", reaches it at " + formatNumber("%.6g", reach);
      }
      u.variantLines.push_back(line);
      u.variantX.push_back(reach);
    }
    for (std::size_t k = 0; k < u.variantLines.size(); ++k)
      u.variantsNote += (k > 1 ? "; " : k ? " " : "") + u.variantLines[k];
  }

  // Combined: the model-form and variant intervals (or the design) widened by the other half-widths, added.
  if (slope) {
    ParameterInterval core = u.modelForm.known() ? u.modelForm : ParameterInterval{x, x};
    if (u.variants.known()) core = {std::min(core.low, u.variants.low), std::max(core.high, u.variants.high)};
    u.combined = {core.low - statistical - discretisation, core.high + statistical + discretisation};
    u.combinedNote = std::string("statistical") + (u.discretisation.known() ? " + discretisation" : "") +
                     (u.modelForm.known() ? " + model form" : "") + (u.variants.known() ? " + variants" : "") + ", added";
    std::string missing;
    if (!u.discretisation.known()) missing += "discretisation";
    if (!u.modelForm.known()) missing += std::string(missing.empty() ? "" : " and ") + "model form";
    if (!missing.empty()) u.combinedNote += "; without " + missing + " (not measured)";
  } else {
    u.combinedNote = problem.dimension() == 1 ? "not formed: no local slope (the search ended without a bracket)"
                                              : "not formed: several parameters have no slope to map the sources onto";
  }
  return u;
}

}  // namespace gradfric::design
