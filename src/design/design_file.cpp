// The design file and the printed result (include/gradfric/design/design_file.hpp).
#include "gradfric/design/design_file.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/hdf5_datasets.hpp"
#include "gradfric/io/provenance.hpp"
#include "gradfric/study/study_file.hpp"

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <optional>

namespace gradfric::design {

namespace {

// The provenance record of the run, collected when the file is planned (the run's start, as the
// other writers date it); saveDesignFile collects it then if the plan came from elsewhere.
std::optional<io::Provenance> runProvenance;

// A free parameter's unit: that of its option (-grading_delta, or -field_<property>_<name>).
std::string parameterUnit(const RunParameters& record, const std::string& name) {
  for (const std::string& option : {"-" + name, "-field_" + name})
    if (const ResolvedOption* o = record.find(option)) return o->unit;
  return "";
}

// Units and description of a column of the tables (docs/design.md).
std::pair<std::string, std::string> columnMeaning(const std::string& column, const Problem& problem,
                                                  const RunParameters& record) {
  const std::string value = problem.kind == TargetKind::Variation ? "relative variation (mu_s - mu_s,0) / mu_s,0"
                                                                  : "mean global mu_s";
  const std::string x = problem.dimension() == 1 ? parameterUnit(record, problem.free[0].name) : "";
  if (column.rfind("x_", 0) == 0 && column != "x_ci95_low" && column != "x_ci95_high")
    return {parameterUnit(record, column.substr(2)), "value of the free parameter " + column.substr(2)};
  if (column == "index") return {"1", "order of the evaluation in the search"};
  if (column == "realisations") return {"1", "realisations the evaluation ran"};
  if (column == "value") return {"1", "the target's quantity: " + value};
  if (column == "ci95_low") return {"1", "lower end of the 95 % confidence interval of value"};
  if (column == "ci95_high") return {"1", "upper end of the 95 % confidence interval of value"};
  if (column == "mu_s") return {"1", "mean global static friction coefficient"};
  if (column == "mu_s_ci95_low") return {"1", "lower end of the 95 % confidence interval of mu_s"};
  if (column == "mu_s_ci95_high") return {"1", "upper end of the 95 % confidence interval of mu_s"};
  if (column == "slope") return {x.empty() || x == "1" ? "1" : "1/" + x, "local slope d value / d parameter at the design"};
  if (column == "x_ci95_low") return {x, "lower end of the design's CI mapped onto the parameter through the slope"};
  if (column == "x_ci95_high") return {x, "upper end of the design's CI mapped onto the parameter through the slope"};
  if (column == "peak_confirmed") return {"1", "1 if the FEM run confirmed its peak"};
  if (column == "reference_mu_s") return {"1", "the FEM's non-graded plate's mu_s (the reference of its variation)"};
  if (column == "reference_peak_confirmed") return {"1", "1 if the FEM's non-graded run confirmed its peak"};
  if (column == "other_model_value")
    return {"1", "the other model's " + value + " at the design (the FEM's, or with -design_model fem the spring blocks'; NaN: not run)"};
  if (column == "reaches_target_at")
    return {x, "where the variant reaches the reference's value at the design model's slope (NaN: no slope)"};
  for (const char* source : {"statistical", "discretisation", "model_form", "variants", "combined"})
    for (const char* end : {"low", "high"})
      if (column == std::string(source) + "_" + end)
        return {x, std::string(end) + " end of the parameter's interval from the " + source +
                       " uncertainty (95 %; NaN: not measured; docs/design.md)"};
  if (column == "cells") return {"1", "hexahedra of the FEM mesh"};
  if (column == "nodes_slid_above_one")
    return {"1", "bottom nodes of the FEM run that slid at mu > 1 before the peak: there its onset depends on the mesh "
                 "(docs/flutter.md); -1: not measured"};
  if (column == "area_slid_above_one") return {"1", "their share of the contact area"};
  if (column == "fem_nx" || column == "fem_ny" || column == "fem_nz")
    return {"1", "hexahedra along " + column.substr(4) + " of the FEM run's mesh"};
  if (column == "fem_reference_mu_s")
    return {"1", "the FEM's non-graded plate's mu_s on the run's mesh (the reference of its variation; NaN: none)"};
  if (column == "reused" || column == "reference_reused")
    return {"1", std::string("1 if the FEM run") + (column == "reused" ? "" : " of the non-graded plate") +
                     " was taken from -design_reuse (an earlier design file or the study table), not run"};
  return {"", column};
}

// One table: a group of described float64 columns along scale, its texts as string attributes.
void writeTable(hid_t file, const study::LadderTable& t, hid_t scale, const Problem& problem,
                const RunParameters& record) {
  io::H5Group group = io::createGroup(file, t.name.c_str());
  for (const auto& [name, value] : t.texts) io::writeStringAttribute(group, name, value);
  for (const auto& [name, values] : t.columns) {
    const auto [units, description] = columnMeaning(name, problem, record);
    const io::H5Dataset d = io::writeDescribedColumn(group, name, values, units, description, scale);
    if (name.find("ci95") != std::string::npos)  // the ensemble's intervals (statistics.hpp), or their image on x
      io::writeStringAttribute(d, "interval", name.rfind("x_", 0) == 0
                                                  ? "the 95 % Student t interval of value mapped through the slope"
                                                  : "95 % Student t (docs/ensemble.md, section 3)");
  }
}

study::LadderTable tableOf(const std::string& name, const Problem& problem, const std::vector<Evaluation>& rows) {
  study::LadderTable t;
  t.name = name;
  std::string phases;
  std::vector<double> index, realisations, value, low, high, mu, muLow, muHigh, aboveOne, aboveOneArea, reused;
  std::vector<double> mesh[3], reference;
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
    aboveOne.push_back(static_cast<double>(e.flutter.nodes));
    aboveOneArea.push_back(e.flutter.areaFraction);
    for (int d = 0; d < 3; ++d) mesh[d].push_back(e.femMesh[d]);
    reused.push_back(e.reused ? 1.0 : 0.0);
    reference.push_back(e.femReference);
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
  if (problem.model == "fem" && name != "model_form")  // the FEM's runs (model_form: the spring blocks')
    t.columns.insert(t.columns.end(), {{"nodes_slid_above_one", aboveOne}, {"area_slid_above_one", aboveOneArea},
                                       {"fem_nx", mesh[0]}, {"fem_ny", mesh[1]}, {"fem_nz", mesh[2]}, {"reused", reused},
                                       {"fem_reference_mu_s", reference}});
  return t;
}

// The parameter's interval from each source, and their combination (one parameter), or each
// source in words.
void printUncertainty(MPI_Comm comm, const Problem& problem, const DesignUncertainty& u) {
  const std::string name = problem.dimension() == 1 ? problem.free[0].name : "the parameters";
  GF_CALL(PetscPrintf(comm, "  Uncertainty of %s (95 %%), source by source:\n", name.c_str()));
  auto line = [&](const char* source, const ParameterInterval& i, const std::string& note) {
    if (i.known())
      GF_CALL(PetscPrintf(comm, "    %-15s [%.6g, %.6g]  %s\n", source, i.low, i.high, note.c_str()));
    else
      GF_CALL(PetscPrintf(comm, "    %-15s %s\n", source, note.c_str()));
  };
  const char* statistical = problem.model == "fem" ? "none: a FEM run has no sampling error (its CI is its value)"
                            : u.statistical.known() ? "the design's CI through the local slope"
                                                    : "the design's CI above (no slope to map it)";
  line("statistical", u.statistical, statistical);
  line("discretisation", u.discretisation, u.discretisationNote);
  line("model form", u.modelForm, u.modelFormNote);
  if (!problem.variants.empty()) {  // a variant per line
    std::string note;
    for (const std::string& l : u.variantLines) note += (note.empty() ? "" : "\n                    ") + l;
    line("variants", u.variants, note);
  }
  line("combined", u.combined, u.combinedNote);
}

}  // namespace

io::OutputPlan planDesignFile(MPI_Comm comm, const Problem& problem) {
  io::OutputPlan plan = study::planStudyFile(comm, problem.output, problem.overwrite);
  runProvenance = io::collectProvenance(comm);  // collective, before any work
  return plan;
}

void saveDesignFile(MPI_Comm comm, const io::OutputPlan& plan, const Problem& problem, const RunParameters& record,
                    const SearchLog& log, const SearchResult& result, const std::optional<Evaluation>& verification,
                    const std::optional<FemVerification>& fem, const std::optional<Evaluation>& springBlocks,
                    const std::vector<Evaluation>& variants, const DesignUncertainty& uncertainty,
                    const RunCounts& runs) {
  if (!runProvenance) runProvenance = io::collectProvenance(comm);
  study::StudyFile file;
  std::string names;
  for (const auto& f : problem.free) names += (names.empty() ? "" : ",") + f.name;
  file.attributes = {{"format", "gradfric-design"},
                     {"status", toString(result.status)},
                     {"method", result.method},
                     {"note", result.note},
                     {"target_type", toString(problem.kind)},
                     {"free_parameters", names},
                     {"model", problem.model},
                     {"realisations_run", std::to_string(runs.realisations)},
                     {"fem_runs", std::to_string(runs.femRuns)},
                     {"fem_runs_reused", std::to_string(runs.femReused)}};
  for (const auto& option : io::optionAttributes(record)) file.attributes.emplace_back(option.name, option.value);
  file.ladders.push_back(tableOf("evaluations", problem, log.all()));
  file.ladders.push_back(tableOf("design", problem, {result.design}));
  if (std::isfinite(result.slope))  // one parameter: its CI through the local slope
    file.ladders.back().columns.insert(file.ladders.back().columns.end(),
                                       {{"slope", {result.slope}},
                                        {"x_ci95_low", {result.parameterLow()}},
                                        {"x_ci95_high", {result.parameterHigh()}}});
  {
    study::LadderTable& design = file.ladders.back();
    const DesignUncertainty& u = uncertainty;
    for (const auto& [name, interval] : {std::pair<const char*, ParameterInterval>{"statistical", u.statistical},
                                         {"discretisation", u.discretisation},
                                         {"model_form", u.modelForm},
                                         {"variants", u.variants},
                                         {"combined", u.combined}}) {
      design.columns.push_back({std::string(name) + "_low", {interval.low}});
      design.columns.push_back({std::string(name) + "_high", {interval.high}});
    }
    design.columns.push_back({"other_model_value", {u.otherValue}});
    design.texts.emplace_back("discretisation_note", u.discretisationNote);
    design.texts.emplace_back("model_form_note", u.modelFormNote);
    design.texts.emplace_back("variants_note", u.variantsNote);
    design.texts.emplace_back("combined_note", u.combinedNote);
  }
  if (verification) file.ladders.push_back(tableOf("verification", problem, {*verification}));
  if (springBlocks) file.ladders.push_back(tableOf("model_form", problem, {*springBlocks}));
  if (!variants.empty()) {  // one row per variant, in -design_variants' order
    study::LadderTable t = tableOf("variants", problem, variants);
    std::string files, options;
    for (const auto& v : problem.variants) {
      files += (files.empty() ? "" : ",") + v.file;
      options += (options.empty() ? "" : "; ") + v.options;
    }
    t.texts.emplace_back("files", files);
    t.texts.emplace_back("options", options);
    t.columns.push_back({"reaches_target_at", uncertainty.variantX});
    file.ladders.push_back(t);
  }
  if (fem) {
    study::LadderTable t;
    t.name = "fem_verification";
    for (const auto& option : io::optionAttributes(problem.fem->record)) t.texts.emplace_back(option.name, option.value);
    const FemRun& r = fem->design;
    t.columns = {{"mu_s", {r.muStatic}}, {"peak_confirmed", {r.peakConfirmed ? 1.0 : 0.0}},
                 {"cells", {double(fem->cells)}}, {"nodes_slid_above_one", {double(r.flutter.nodes)}},
                 {"area_slid_above_one", {r.flutter.areaFraction}}, {"reused", {r.reused ? 1.0 : 0.0}}};
    if (fem->reference)
      t.columns.insert(t.columns.end(), {{"reference_mu_s", {fem->reference->muStatic}},
                                         {"reference_peak_confirmed", {fem->reference->peakConfirmed ? 1.0 : 0.0}},
                                         {"reference_reused", {fem->reference->reused ? 1.0 : 0.0}}});
    t.columns.push_back({"value", {uncertainty.otherValue}});
    file.ladders.push_back(t);
  }
  // The conventions of the other results files (io/hdf5_attributes.hpp): UTF-8 string attributes,
  // described datasets on named axes (/evaluation, /row), the provenance record in /provenance.
  plan.writeOnRank0(comm, [&](const std::string& path) {
    io::H5File out(GF_H5(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)));
    for (const auto& [name, value] : file.attributes) io::writeStringAttribute(out, name, value);
    const io::H5Dataset evaluation =
        io::createIndexScale(out, "evaluation", file.ladders.front().columns.front().second.size(), "evaluation index (row of /evaluations)");
    const io::H5Dataset row =
        io::createIndexScale(out, "row", 1, "the one row of /design, /verification, /model_form and /fem_verification");
    const io::H5Dataset variant =
        variants.empty() ? io::H5Dataset() : io::createIndexScale(out, "variant", variants.size(), "-design_variants' files, in order (row of /variants)");
    for (const auto& t : file.ladders)
      writeTable(out, t, t.name == "evaluations" ? evaluation.get() : t.name == "variants" ? variant.get() : row.get(), problem,
                 record);
    io::H5Group provenance = io::createGroup(out, "provenance");
    io::writeProvenance(provenance, *runProvenance);
    GF_H5(H5Fflush(out, H5F_SCOPE_GLOBAL));  // a full disk shows here, not in a silent close
  });
  plan.commit(comm);
}

void printDesign(MPI_Comm comm, const Problem& problem, const SearchResult& result,
                 const std::optional<Evaluation>& verification, const std::optional<FemVerification>& fem,
                 const std::optional<Evaluation>& springBlocks, const std::vector<Evaluation>& variants,
                 const DesignUncertainty& uncertainty, const RunCounts& runs, double wallSeconds,
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
  row(problem.model == "fem" ? "search (FEM)" : "search", d);
  if (std::isfinite(result.slope))
    GF_CALL(PetscPrintf(comm, "  %s in [%.6g, %.6g] (the design's CI through the local slope %.4g)\n",
                        problem.free[0].name.c_str(), result.parameterLow(), result.parameterHigh(), result.slope));
  if (verification) row("verification", *verification);
  if (springBlocks) row("spring blocks", *springBlocks);
  for (std::size_t k = 0; k < variants.size(); ++k) row(("variant " + std::to_string(k + 1)).c_str(), variants[k]);
  if (problem.model == "fem")
    GF_CALL(PetscPrintf(comm, "  no verification ensemble: a FEM run is deterministic (the same run gives the same number)\n"));
  if (fem) {
    char femValue[32] = "";
    if (std::isfinite(uncertainty.otherValue)) std::snprintf(femValue, sizeof femValue, "%.6f", uncertainty.otherValue);
    // A run taken from -design_reuse says so in place of its time.
    const auto source = [](const FemRun& r) {
      return r.reused ? std::string("taken from -design_reuse") : formatNumber("%.1f s", r.wallSeconds);
    };
    GF_CALL(PetscPrintf(comm, "  %-13s %4s %12s %26s %12.6f%s   (%d hexahedra, %s)\n", "FEM", "1", femValue, "",
                        fem->design.muStatic, fem->design.peakConfirmed ? "" : " (peak not confirmed)", fem->cells,
                        source(fem->design).c_str()));
    if (fem->reference)
      GF_CALL(PetscPrintf(comm, "  %-13s %4s %12s %26s %12.6f%s   (the FEM's non-graded plate, %s)\n", "FEM, uniform", "1",
                          "", "", fem->reference->muStatic, fem->reference->peakConfirmed ? "" : " (peak not confirmed)",
                          source(*fem->reference).c_str()));
  }
  // The FEM's value at the design rests on an ill-posed interface where nodes slid at mu > 1.
  const FlutterExposure exposed = problem.model == "fem" ? d.flutter : fem ? fem->design.flutter : FlutterExposure{};
  if (exposed.nodes > 0)
    GF_CALL(PetscPrintf(comm,
                        "  flutter: %ld FEM nodes (%.3g %% of the area) slid at mu > 1 before the peak at the design, so "
                        "the FEM's onset there depends on the mesh (docs/flutter.md); the high-friction edge leading "
                        "avoids it\n",
                        exposed.nodes, 100 * exposed.areaFraction));
  GF_CALL(PetscPrintf(comm, "  target %s = %g +- %g%s\n", quantity, problem.target, problem.tolerance,
                      verification ? (verification->side(problem.target) == 0 ? "; the verification's CI holds it"
                                                                               : "; the verification's CI misses it")
                                   : ""));
  printUncertainty(comm, problem, uncertainty);
  if (runs.femRuns > 0 || runs.femReused > 0)
    GF_CALL(PetscPrintf(comm, "  %ld FEM runs (any non-graded plate included)%s and %ld spring-block realisations, %.1f s wall\n",
                        runs.femRuns,
                        runs.femReused > 0 ? (", " + std::to_string(runs.femReused) + " more taken from -design_reuse").c_str() : "",
                        runs.realisations, wallSeconds));
  else
    GF_CALL(PetscPrintf(comm, "  %ld realisations run (the verification, any reference plate and any variants included), %.1f s wall\n",
                        runs.realisations, wallSeconds));
  GF_CALL(PetscPrintf(comm, "design file: %s\n", path.c_str()));
}

}  // namespace gradfric::design
