#pragma once
// The design's parameter interval from each source of uncertainty, named, and their combination
// (docs/design.md, "The whole uncertainty of a design"). One free parameter, through the local
// slope s = d value / d x of the search:
//  - statistical: the design's 95 % CI, +- h / |s|;
//  - discretisation: the spring blocks' study bar of mu_s at the design's scene and lattice
//    (study::studyBar), +- U / |s|; not measured where no ladder covers the design point;
//  - model form: the other model at the design point: with the spring blocks, the FEM
//    (-design_verify_fem; for a variation target against the FEM's own non-graded plate); with
//    -design_model fem, a spring-block ensemble. At the design model's slope, the other reaches
//    the same value at x_O = x - (v_other - v_design) / s; the interval runs from x to x_O.
//  - variants (-design_variants): the spring-block variants the designer names, each one ensemble at
//    the design on the verification's streams (paired with it; without a verification, the search's
//    stream and value). Variant k reaches the reference value v at x_k = x - (v_k - v) / s; the
//    interval is the hull of x and every x_k +- h_k / |s| (h_k: the variant's CI half-width).
// Combined: the hull of the model-form and variant intervals widened by the statistical and discretisation
// half-widths, added, not in quadrature: a bound whenever each part is one. Several free
// parameters have no slope: each source is then reported in the target's quantity only.
#include "gradfric/core/study_table.hpp"
#include "gradfric/design/fem_check.hpp"
#include "gradfric/design/search.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::design {

struct ParameterInterval {
  double low = std::numeric_limits<double>::quiet_NaN();
  double high = std::numeric_limits<double>::quiet_NaN();
  bool known() const { return std::isfinite(low) && std::isfinite(high); }
};

struct DesignUncertainty {
  ParameterInterval statistical;
  ParameterInterval discretisation;
  std::string discretisationNote;  // the bar and its ladder, or why it is not measured
  ParameterInterval modelForm;
  std::string modelFormNote;       // the other model's value against the design's, or why not measured
  double otherValue = std::numeric_limits<double>::quiet_NaN();  // the other model's target quantity at the design
  ParameterInterval variants;
  std::string variantsNote;        // each variant against the reference, or why not measured (stored)
  std::vector<std::string> variantLines;  // the same, the reference first, then one per variant (printed)
  std::vector<double> variantX;    // per variant: where it reaches the reference value (NaN: no slope)
  ParameterInterval combined;
  std::string combinedNote;        // which sources it holds
};

// otherValue: the other model's mu_s or variation at the design (NaN: not run). bar: the design
// model's study bar of mu_s at the design point (absolute uncertainty in its verdict). variants:
// the variants' ensembles at the design, against `reference` (the verification, or the design).
DesignUncertainty designUncertainty(const Problem& problem, const SearchResult& result, double otherValue,
                                    const study::StudyBar& bar, const std::vector<Evaluation>& variants = {},
                                    const Evaluation* reference = nullptr);

// The design model's study bar of the target's quantity at the design point x (sbm_study.tsv at the
// lattice N_b, or fem_study.tsv at the -fem_* mesh; the scene's options with the design's grading
// amplitude): of mu_s, or of a variation's ladder against the non-graded plate
// (study::variationBar). A field parameter's design point is not looked up: not measured, said so.
study::StudyBar designStudyBar(const Problem& problem, const RunParameters& record, const std::vector<double>& x);

// The study-table scene of one run of the design's family with grading g, in the FEM (fem) or
// the spring blocks: the scene's options with g's, less the design's own. The key designStudyBar
// looks up, and the one a study-table row must have to stand for a run (-design_reuse).
study::SceneKey designRunScene(const Problem& problem, const RunParameters& record, const Grading& g, bool fem);

// The FEM's value of the target's quantity: mu_s, or (mu_s - mu_s,0) / mu_s,0 against its own
// non-graded run; NaN when a run did not confirm its peak.
double femTargetValue(const Problem& problem, const FemVerification& fem);

}  // namespace gradfric::design
