// The accuracy-cost study of the finite-element plate (include/gradfric/study/fem_study.hpp), as
// named steps: read the options, plan the file, build the ladders, run them (and the timed
// estimates), tabulate the errors, save, print. The runs: src/study/fem_study_runs.cpp.
#include "gradfric/study/fem_study.hpp"
#include "gradfric/study/study_file.hpp"

#include "fem_study_steps.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/parameter_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace gradfric::study {

namespace fem_study {

namespace {

// "25x25x1,50x50x2" -> {{25,25,1},{50,50,2}}; an empty item or anything after nz (6x6x1.5 would
// run 6x6x1) is refused.
std::vector<Mesh> parseMeshes(const OptionReader& o, const std::string& name, const std::string& text) {
  std::vector<Mesh> meshes;
  if (text.empty()) return meshes;
  const char* allowed = "comma-separated meshes nx x ny x nz of whole numbers >= 1, e.g. 25x25x1,50x50x2";
  std::stringstream list(text + ",");  // the comma makes a trailing empty item visible
  std::string item;
  while (std::getline(list, item, ',')) {
    Mesh m{0, 0, 0};
    char x1 = 0, x2 = 0;
    std::stringstream s(item);
    if (!(s >> m[0] >> x1 >> m[1] >> x2 >> m[2]) || x1 != 'x' || x2 != 'x' || m[0] < 1 || m[1] < 1 || m[2] < 1 ||
        (s >> std::ws, !s.eof()))
      throw InputError(o.fullName(name), text,
                       std::string(allowed) + " ('" + item + "' is not" + (item.empty() ? ": an empty item)" : " one)"));
    if (double(m[0]) * m[1] * m[2] > 2e7)  // as -fem_nx/ny/nz: memory before any work
      throw InputError(o.fullName(name), item, "meshes of at most 2e7 hexahedra");
    meshes.push_back(m);
  }
  return meshes;
}

}  // namespace

fem::FemParameters Study::onMesh(const Mesh& m) const {
  fem::FemParameters q = base;
  q.nx = m[0];
  q.ny = m[1];
  q.nz = m[2];
  return q;
}

std::optional<Study> readStudy(MPI_Comm comm, RunParameters* record) {
  Study s;
  s.grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  s.base = fem::readFemParameters(comm, record, plate);
  OptionReader o(comm, "study_", "Accuracy-cost study (finite-element plate)", record);
  s.knobs = o.choiceList("knobs", {"mesh", "dt", "kn", "kt"}, {"mesh", "dt", "kn", "kt"},
                         "ladders to run: mesh, time-step safety factor per integrator, penalty stiffnesses");
  const std::string meshText =
      o.text("meshes", "25x25x1,50x50x2,100x100x5", "mesh ladder nx x ny x nz (the last is the reference)");
  const std::string estimateText = o.text(
      "mesh_estimate", "", "meshes too big to run through: time a short run and estimate the full cost (e.g. 200x200x10)");
  s.meshSafety = o.real("mesh_dt_safety", 0.3, "1",
                        "dt safety of the mesh ladder (small, so that the dt error does not mask the mesh error)");
  const PetscInt estimateSteps = o.integer("mesh_estimate_steps", 40, 1, 1000000, "1", "steps of that short run");
  s.integrators = o.choiceList("integrators", {"gfverlet", "rk4", "ssp"}, {"gfverlet", "rk4", "ssp"},
                               "integrators of the dt ladder (gfverlet first: its finest rung is the reference)");
  s.safeties = o.realList("dt_safety", {0.1, 0.2, 0.3, 0.5, 0.7, 0.9}, "1",
                          "dt ladder of gfverlet, fraction of the stable step (smallest is the reference)");
  s.safetiesOther = o.realList("dt_safety_other", {0.3, 0.6, 0.9}, "1",
                               "dt ladder of the other integrators (same fractions of the same stable step)");
  s.factors = o.realList("penalty_factors", {0.1, 0.3, 1, 3, 10, 30}, "1",
                         "k_n and k_t ladders: factor on the default 250 G/H (largest is the reference)");
  s.penaltySafety = o.real("penalty_dt_safety", 0.5, "1", "dt safety of the penalty ladders");
  s.fineSafeties = o.realList("fine_dt_safety", {}, "1",
                              "optional dt ladder (gfverlet) on the mesh ladder's finest mesh (empty: none)");
  OptionReader out(comm, "", "Results file", record);
  s.output = out.text("output", "gradfric_study_fem.h5", "study results file (HDF5)");
  s.overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  if (helpRequested()) return std::nullopt;
  s.meshes = parseMeshes(o, "meshes", meshText);
  s.estimates = parseMeshes(o, "mesh_estimate", estimateText);
  if (s.meshes.empty()) throw InputError(o.fullName("meshes"), meshText, "at least one mesh");
  o.requireAtLeast("mesh_estimate_steps", estimateSteps, 2);
  s.estimateSteps = int(estimateSteps);
  for (auto* list : {&s.safeties, &s.safetiesOther, &s.fineSafeties})
    for (double x : *list) o.requireRange("dt_safety", x, 1e-6, 1.0, "0 < safety <= 1");
  for (double f : s.factors) o.requireRange("penalty_factors", f, 1e-6, 1e6, "1e-6 <= factor <= 1e6");
  o.requireRange("penalty_dt_safety", s.penaltySafety, 1e-6, 1.0, "0 < safety <= 1");
  o.requireRange("mesh_dt_safety", s.meshSafety, 1e-6, 1.0, "0 < safety <= 1");
  if (s.base.dt) throw InputError("-fem_dt", "(set)", "unset: the study sets the step as a fraction of the stable step");
  checkUnusedOptions(comm, {"study_", "plate_", "surface_", "fem_", "grading_", "output"});
  for (auto* list : {&s.safeties, &s.safetiesOther, &s.factors, &s.fineSafeties}) std::sort(list->begin(), list->end());
  s.base.verbose = false;
  return s;
}

std::vector<Ladder> buildLadders(const Study& s) {
  std::vector<Ladder> ladders;
  auto want = [&](const char* k) { return std::find(s.knobs.begin(), s.knobs.end(), k) != s.knobs.end(); };
  auto dtLadder = [](const std::string& name, const std::string& meaning, int reference) {
    return Ladder{name, "dt_safety", "1 (fraction of the stable step)", meaning, {}, {}, {}, {}, reference};
  };
  auto addRung = [](Ladder* l, double value, const fem::FemParameters& q, const std::string& integrator) {
    l->values.push_back(value);
    l->runs.push_back(q);
    l->integrators.push_back(integrator);
  };
  if (want("dt")) {
    for (const auto& name : s.integrators) {
      Ladder l = dtLadder("dt_" + name, "|mu/mu_ref - 1|, reference: the smallest dt_safety of the first integrator", -1);
      for (double safety : name == s.integrators.front() ? s.safeties : s.safetiesOther) {
        fem::FemParameters q = s.base;
        q.dtSafety = safety;
        addRung(&l, safety, q, name);
      }
      ladders.push_back(l);
    }
  }
  for (const char* which : {"kn", "kt"}) {
    if (!want(which)) continue;
    Ladder l{which, std::string(which) == "kn" ? "k_n factor" : "k_t factor", "1 (x the default 250 G/H)",
             "|mu/mu_ref - 1|, reference: the stiffest penalty", {}, {}, {}, {}, int(s.factors.size()) - 1};
    for (double f : s.factors) {
      fem::FemParameters q = s.base;
      if (which[1] == 'n') q.kn = f * s.base.kn;
      else q.kt = f * s.base.kt;
      q.dtSafety = s.penaltySafety;
      addRung(&l, f, q, "gfverlet");
    }
    ladders.push_back(l);
  }
  if (want("mesh")) {
    Ladder l{"mesh", "nx", "1 (nx x nx x nz hexahedra)", "|mu/mu_ref - 1|, reference: the finest mesh", {}, {}, {}, {},
             int(s.meshes.size()) - 1};
    for (const auto& m : s.meshes) {
      fem::FemParameters q = s.onMesh(m);
      q.dtSafety = s.meshSafety;
      addRung(&l, m[0], q, "gfverlet");
    }
    ladders.push_back(l);
    if (!s.fineSafeties.empty()) {
      Ladder f = dtLadder("dt_fine_mesh", "|mu/mu_ref - 1|, reference: the smallest dt_safety on the finest mesh", 0);
      for (double safety : s.fineSafeties) {
        fem::FemParameters q = s.onMesh(s.meshes.back());
        q.dtSafety = safety;
        addRung(&f, safety, q, "gfverlet");
      }
      ladders.push_back(f);
    }
  }
  return ladders;
}

namespace {

// The errors of every ladder against its reference rung (the dt ladders: the first one's finest).
std::vector<LadderTable> errorTables(const std::vector<Ladder>& ladders, const std::vector<Estimate>& estimates) {
  const Ladder* dtReference = nullptr;
  for (const auto& l : ladders)
    if (l.knob == "dt_safety" && l.reference < 0 && !dtReference) dtReference = &l;
  std::vector<LadderTable> tables;
  for (const auto& l : ladders) {
    const Outcome& ref = l.reference >= 0 ? l.outcomes[l.reference] : dtReference->outcomes.front();
    const std::size_t n = l.values.size();
    std::vector<double> es(n), ek(n), wall(n), cpu(n), muS(n), muK(n), dt(n), steps(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Outcome& r = l.outcomes[i];
      es[i] = std::fabs(r.muS / ref.muS - 1);
      ek[i] = std::fabs(r.muK / ref.muK - 1);
      wall[i] = r.wall;
      cpu[i] = r.cpu;
      muS[i] = r.muS;
      muK[i] = r.muK;
      dt[i] = r.dt;
      steps[i] = r.steps;
    }
    LadderTable t;
    t.name = l.name;
    t.texts = {{"knob", l.knob}, {"unit", l.unit}, {"error_meaning", l.meaning}, {"integrator", l.integrators.front()}};
    t.columns = {{"setting", l.values}, {"mu_s_error", es}, {"mu_k_error", ek}, {"wall_seconds", wall},
                 {"cpu_seconds", cpu},  {"mu_s", muS},      {"mu_k", muK},      {"dt", dt},
                 {"steps", steps}};
    if (l.name == "mesh") {
      // Meshes timed by a short run only (an attribute: plot_accuracy.py reads every group as a ladder).
      std::string text;
      for (const auto& r : estimates) {
        char line[200];
        std::snprintf(line, sizeof line, "%snx %g: %.2f ms/step, ~%.0f steps, ~%.0f s", text.empty() ? "" : "; ", r[0],
                      r[1], r[2], r[3]);
        text += line;
      }
      if (!text.empty()) t.texts.emplace_back("estimates", text);
    }
    tables.push_back(t);
  }
  return tables;
}

void printTables(MPI_Comm comm, const std::vector<Ladder>& ladders, const std::vector<LadderTable>& tables,
                 const std::string& output) {
  GF_CALL(PetscPrintf(comm, "\n%-14s %-8s %12s %12s %10s %10s %9s %9s %8s\n", "ladder", "setting", "mu_s rel.err",
                      "mu_k rel.err", "mu_s", "mu_k", "wall [s]", "cpu [s]", "steps"));
  for (std::size_t k = 0; k < ladders.size(); ++k) {
    const Ladder& l = ladders[k];
    const auto& c = tables[k].columns;  // setting, mu_s_error, mu_k_error, ...
    for (std::size_t i = 0; i < l.values.size(); ++i) {
      const Outcome& r = l.outcomes[i];
      GF_CALL(PetscPrintf(comm, "%-14s %-8s %12.3e %12.3e %10.6f %10.6f %9.2f %9.2f %8.0f%s\n", l.name.c_str(),
                          formatReal(l.values[i]).c_str(), c[1].second[i], c[2].second[i], r.muS, r.muK, r.wall,
                          r.cpu, r.steps, r.failure.empty() ? "" : "  (failed)"));
    }
  }
  GF_CALL(PetscPrintf(comm, "\nstudy results in %s\n", output.c_str()));
}

}  // namespace

}  // namespace fem_study

void runFiniteElementStudy(MPI_Comm comm, RunParameters* record) {
  using namespace fem_study;
  const std::optional<Study> study = readStudy(comm, record);
  if (!study) return;  // -help
  const io::OutputPlan plan = planStudyFile(comm, study->output, study->overwrite);
  std::vector<Ladder> ladders = buildLadders(*study);
  const StudyTimer timer = startStudy(comm, ladders);
  runLadders(comm, *study, &ladders);
  const std::vector<Estimate> estimates = runEstimates(comm, *study, ladders);
  finishStudy(comm, timer, record);
  const std::vector<LadderTable> tables = errorTables(ladders, estimates);
  saveStudyFile(comm, plan, {studyAttributes(*record, {{"model", "fem"}}), tables});
  printTables(comm, ladders, tables, plan.path());
}

}  // namespace gradfric::study
