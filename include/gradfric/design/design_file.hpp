#pragma once
// The design file (HDF5, layout in docs/design.md) and the printed result. The file is planned
// before any work (-output, -output_overwrite: refused on every rank alike), written by rank 0
// under <output>.partial and renamed into place when complete: whole or not at all.
//   /            string attributes: format = gradfric-design, status, method, note, target_type,
//                free_parameters, model (sbm, fem), then every option of the run
//   /evaluations every evaluation in order: index, x_<parameter> ..., realisations, value,
//                ci95_low, ci95_high, mu_s, mu_s_ci95_low, mu_s_ci95_high; attribute phases
//   /design      the design (one row, same columns; one parameter: slope, x_ci95_low, x_ci95_high,
//                its CI mapped onto the parameter through the local slope, and each source's
//                interval of the parameter, NaN where not measured: statistical_, discretisation_,
//                model_form_, variants_, combined_ low/high; other_model_value; attributes *_note say why)
//   /model_form  with -design_model fem: the spring blocks' ensemble at the design (one row)
//   /variants    with -design_variants: each variant's ensemble at the design (a row per file, along
//                /variant; reaches_target_at; attributes files, options)
//   /verification  the fresh ensemble at the design (one row; absent with -design_verify false)
//   /fem_verification  with -design_verify_fem: mu_s, peak_confirmed, cells (a variation target:
//                reference_mu_s, reference_peak_confirmed of the FEM's non-graded plate); value (the
//                target's quantity); attributes: the -fem_* options
#include "gradfric/design/fem_check.hpp"
#include "gradfric/design/search.hpp"
#include "gradfric/design/uncertainty.hpp"
#include "gradfric/io/output_plan.hpp"

#include <mpi.h>

#include <optional>

namespace gradfric::design {

// What a design ran: spring-block realisations (the verification, the reference plate, the
// model-form ensemble and the variants included) and FEM runs.
struct RunCounts {
  long realisations = 0;
  long femRuns = 0;
  long femReused = 0;  // FEM runs taken from -design_reuse instead
};

// Collective, before any work.
io::OutputPlan planDesignFile(MPI_Comm comm, const Problem& problem);

// Collective: writes and commits the file.
void saveDesignFile(MPI_Comm comm, const io::OutputPlan& plan, const Problem& problem, const RunParameters& record,
                    const SearchLog& log, const SearchResult& result, const std::optional<Evaluation>& verification,
                    const std::optional<FemVerification>& fem, const std::optional<Evaluation>& springBlocks,
                    const std::vector<Evaluation>& variants, const DesignUncertainty& uncertainty,
                    const RunCounts& runs);

// Rank 0 prints the design, its verification and how the search went.
void printDesign(MPI_Comm comm, const Problem& problem, const SearchResult& result,
                 const std::optional<Evaluation>& verification, const std::optional<FemVerification>& fem,
                 const std::optional<Evaluation>& springBlocks, const std::vector<Evaluation>& variants,
                 const DesignUncertainty& uncertainty, const RunCounts& runs, double wallSeconds,
                 const std::string& path);

}  // namespace gradfric::design
