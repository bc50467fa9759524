// The design file and the printed result (include/gradfric/design/design_file.hpp).
#include "gradfric/design/design_file.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/study/study_file.hpp"

#include <petscsys.h>

#include <cmath>

namespace gradfric::design {

namespace {

study::LadderTable tableOf(const std::string& name, const Problem& problem, const std::vector<Evaluation>& rows) {
  study::LadderTable t;
  t.name = name;
  std::string phases;
  std::vector<double> index, realisations, value, low, high, mu, muLow, muHigh;
  std::vector<std::vector<double>> x(problem.dimension());
  for (const auto& e : rows) {
    phases += (phases.empty() ? "" : ",") + e.phase;
    index.push_back(e.index);
    for (int i = 0; i < problem.dimension(); ++i) x[i].push_back(e.x[i]);
    realisations.push_back(e.realisations);
    value.push_back(e.value);
    low.push_back(e.ciLow);
    high.push_back(e.ciHigh);
    mu.push_back(e.muStatic);
    muLow.push_back(e.muStaticCiLow);
    muHigh.push_back(e.muStaticCiHigh);
  }
  t.texts = {{"phases", phases},
             {"value_meaning", problem.kind == TargetKind::Variation ? "relative variation (mu_s - mu_s,0) / mu_s,0"
                                                                     : "mean mu_s"}};
  t.columns = {{"index", index}};
  for (int i = 0; i < problem.dimension(); ++i) t.columns.emplace_back("x_" + problem.free[i].name, x[i]);
  t.columns.insert(t.columns.end(), {{"realisations", realisations},
                                     {"value", value},
                                     {"ci95_low", low},
                                     {"ci95_high", high},
                                     {"mu_s", mu},
                                     {"mu_s_ci95_low", muLow},
                                     {"mu_s_ci95_high", muHigh}});
  return t;
}

}  // namespace

io::OutputPlan planDesignFile(MPI_Comm comm, const Problem& problem) {
  return study::planStudyFile(comm, problem.output, problem.overwrite);
}

void saveDesignFile(MPI_Comm comm, const io::OutputPlan& plan, const Problem& problem, const RunParameters& record,
                    const SearchLog& log, const SearchResult& result, const std::optional<Evaluation>& verification,
                    const std::optional<FemVerification>& fem, long realisationsRun) {
  study::StudyFile file;
  std::string names;
  for (const auto& f : problem.free) names += (names.empty() ? "" : ",") + f.name;
  file.attributes = {{"format", "gradfric-design"},
                     {"status", toString(result.status)},
                     {"method", result.method},
                     {"note", result.note},
                     {"target_type", toString(problem.kind)},
                     {"free_parameters", names},
                     {"realisations_run", std::to_string(realisationsRun)}};
  for (const auto& option : record.all())
    file.attributes.emplace_back(option.name[0] == '-' ? option.name.substr(1) : option.name, option.value);
  file.ladders.push_back(tableOf("evaluations", problem, log.all()));
  file.ladders.push_back(tableOf("design", problem, {result.design}));
  if (std::isfinite(result.slope))  // one parameter: its CI through the local slope
    file.ladders.back().columns.insert(file.ladders.back().columns.end(),
                                       {{"slope", {result.slope}},
                                        {"x_ci95_low", {result.parameterLow()}},
                                        {"x_ci95_high", {result.parameterHigh()}}});
  if (verification) file.ladders.push_back(tableOf("verification", problem, {*verification}));
  if (fem) {
    study::LadderTable t;
    t.name = "fem_verification";
    for (const auto& option : problem.fem->record.all())
      t.texts.emplace_back(option.name[0] == '-' ? option.name.substr(1) : option.name, option.value);
    t.columns = {{"mu_s", {fem->muStatic}}, {"peak_confirmed", {fem->peakConfirmed ? 1.0 : 0.0}},
                 {"cells", {double(fem->cells)}}};
    file.ladders.push_back(t);
  }
  study::saveStudyFile(comm, plan, file);
}

void printDesign(MPI_Comm comm, const Problem& problem, const SearchResult& result,
                 const std::optional<Evaluation>& verification, const std::optional<FemVerification>& fem,
                 long realisationsRun, double wallSeconds,
                 const std::string& path) {
  const char* quantity = problem.kind == TargetKind::Variation ? "relative variation" : "mu_s";
  const Evaluation& d = result.design;
  GF_CALL(PetscPrintf(comm, "\nDesign (%s, %s): %s\n  %s\n", result.method.c_str(), toString(result.status),
                      problem.describe(d.x).c_str(), result.note.c_str()));
  GF_CALL(PetscPrintf(comm, "  %-13s %4s %12s %26s %12s %26s\n", "ensemble", "R", quantity, "95% CI", "mu_s", "95% CI"));
  auto row = [&](const char* name, const Evaluation& e) {
    GF_CALL(PetscPrintf(comm, "  %-13s %4d %12.6f      [%9.6f, %9.6f] %12.6f      [%9.6f, %9.6f]\n", name, e.realisations,
                        e.value, e.ciLow, e.ciHigh, e.muStatic, e.muStaticCiLow, e.muStaticCiHigh));
  };
  row("search", d);
  if (std::isfinite(result.slope))
    GF_CALL(PetscPrintf(comm, "  %s in [%.6g, %.6g] (the design's CI through the local slope %.4g)\n",
                        problem.free[0].name.c_str(), result.parameterLow(), result.parameterHigh(), result.slope));
  if (verification) row("verification", *verification);
  if (fem)
    GF_CALL(PetscPrintf(comm, "  %-13s %4s %12s %26s %12.6f%s   (%d hexahedra, %.1f s)\n", "FEM", "1", "", "", fem->muStatic,
                        fem->peakConfirmed ? "" : " (peak not confirmed)", fem->cells, fem->wallSeconds));
  GF_CALL(PetscPrintf(comm, "  target %s = %g +- %g%s\n", quantity, problem.target, problem.tolerance,
                      verification ? (verification->side(problem.target) == 0 ? "; the verification's CI holds it"
                                                                               : "; the verification's CI misses it")
                                   : ""));
  GF_CALL(PetscPrintf(comm, "  %ld realisations run (the verification and any reference plate included), %.1f s wall\n",
                      realisationsRun, wallSeconds));
  GF_CALL(PetscPrintf(comm, "design file: %s\n", path.c_str()));
}

}  // namespace gradfric::design
