#include "gradfric/study/fem_study.hpp"
#include "gradfric/study/study_file.hpp"

#include <petscsection.h>
#include <petscsf.h>

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"

#include <petscsys.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace gradfric::study {

namespace {

struct Outcome {
  double muS = NAN, muK = NAN, wall = NAN, cpu = NAN, steps = 0, dt = 0, stableDt = 0;
  bool windowComplete = false;
  std::string failure;  // non-empty: the run stopped (blow-up monitor, PETSc error)
};

struct Ladder {
  std::string name, knob, unit, meaning;
  std::vector<double> values;           // the setting of each rung
  std::vector<fem::FemParameters> runs;  // the parameters of each rung
  std::vector<std::string> integrators;  // per rung: gfverlet, rk4, ssp
  std::vector<Outcome> outcomes;
  int reference = -1;  // rung of this ladder used as reference (-1: the first dt ladder's)
};

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec) + double(u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_stime.tv_usec);
}

std::string loadAverage() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

// "25x25x1,50x50x2" -> {{25,25,1},{50,50,2}}
std::vector<std::array<int, 3>> parseMeshes(const OptionReader& o, const std::string& name, const std::string& text) {
  std::vector<std::array<int, 3>> meshes;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) continue;
    std::array<int, 3> m{0, 0, 0};
    char x1 = 0, x2 = 0;
    std::stringstream s(item);
    if (!(s >> m[0] >> x1 >> m[1] >> x2 >> m[2]) || x1 != 'x' || x2 != 'x' || m[0] < 1 || m[1] < 1 || m[2] < 1)
      throw InputError(o.fullName(name), text, "comma-separated meshes nx x ny x nz, e.g. 25x25x1,50x50x2");
    if (double(m[0]) * m[1] * m[2] > 2e7)  // as -fem_nx/ny/nz: memory before any work
      throw InputError(o.fullName(name), item, "meshes of at most 2e7 hexahedra");
    meshes.push_back(m);
  }
  return meshes;
}

// The integrator through PETSc's options (createPlateTS calls TSSetFromOptions).
void selectIntegrator(const std::string& name) {
  GF_CALL(PetscOptionsClearValue(nullptr, "-ts_type"));
  GF_CALL(PetscOptionsClearValue(nullptr, "-ts_rk_type"));
  if (name == "rk4") {
    GF_CALL(PetscOptionsSetValue(nullptr, "-ts_type", "rk"));
    GF_CALL(PetscOptionsSetValue(nullptr, "-ts_rk_type", "4"));
  } else if (name == "ssp") {
    GF_CALL(PetscOptionsSetValue(nullptr, "-ts_type", "ssp"));
  }
}

Outcome runOne(MPI_Comm comm, const fem::FemParameters& q, const Grading& grading, const std::string& integrator) {
  Outcome out;
  out.stableDt = fem::stableTimeStep(q, grading);
  out.dt = q.dt > 0 ? q.dt : q.dtSafety * out.stableDt;
  selectIntegrator(integrator);
  GF_CALL_MPI(MPI_Barrier(comm));
  const double w0 = MPI_Wtime(), c0 = cpuSeconds();
  try {
    fem::PlateModel model(comm, q, grading);
    const fem::FemRunResult r = fem::runPlateExperiment(model);
    out.muS = r.muS;
    out.muK = r.muK;
    out.steps = double(r.steps);
    out.dt = r.dt;
    out.stableDt = r.stableDt;
    out.windowComplete = r.windowComplete;
  } catch (const InputError&) {
    selectIntegrator("gfverlet");
    throw;
  } catch (const std::exception& e) {
    // Every rank sees the same collective monitor values, so every rank lands here.
    out.failure = e.what();
  }
  out.wall = MPI_Wtime() - w0;
  out.cpu = cpuSeconds() - c0;
  selectIntegrator("gfverlet");
  return out;
}

}  // namespace

void runFiniteElementStudy(MPI_Comm comm, RunParameters* record) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));

  const Grading grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  fem::FemParameters base = fem::readFemParameters(comm, record, plate);
  PetscBool knSet = PETSC_FALSE, ktSet = PETSC_FALSE, dtSet = PETSC_FALSE;
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-fem_kn", &knSet));
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-fem_kt", &ktSet));
  GF_CALL(PetscOptionsHasName(nullptr, nullptr, "-fem_dt", &dtSet));
  OptionReader o(comm, "study_", "Accuracy-cost study (finite-element plate)", record);
  const auto knobs = o.choiceList("knobs", {"mesh", "dt", "kn", "kt"}, {"mesh", "dt", "kn", "kt"},
                                  "ladders to run: mesh, time-step safety factor per integrator, penalty stiffnesses");
  const std::string meshText =
      o.text("meshes", "25x25x1,50x50x2,100x100x5", "mesh ladder nx x ny x nz (the last is the reference)");
  const std::string estimateText = o.text(
      "mesh_estimate", "", "meshes too big to run through: time a short run and estimate the full cost (e.g. 200x200x10)");
  const double meshSafety = o.real("mesh_dt_safety", 0.3, "1",
                                   "dt safety of the mesh ladder (small, so that the dt error does not mask the mesh error)");
  const PetscInt estimateSteps = o.integer("mesh_estimate_steps", 40, 1, 1000000, "1", "steps of that short run");
  const auto integrators = o.choiceList("integrators", {"gfverlet", "rk4", "ssp"}, {"gfverlet", "rk4", "ssp"},
                                        "integrators of the dt ladder (gfverlet first: its finest rung is the reference)");
  auto safeties = o.realList("dt_safety", {0.1, 0.2, 0.3, 0.5, 0.7, 0.9}, "1",
                             "dt ladder of gfverlet, fraction of the stable step (smallest is the reference)");
  auto safetiesOther = o.realList("dt_safety_other", {0.3, 0.6, 0.9}, "1",
                                  "dt ladder of the other integrators (same fractions of the same stable step)");
  auto factors = o.realList("penalty_factors", {0.1, 0.3, 1, 3, 10, 30}, "1",
                            "k_n and k_t ladders: factor on the default E0/hz (largest is the reference)");
  const double penaltySafety = o.real("penalty_dt_safety", 0.5, "1", "dt safety of the penalty ladders");
  auto paperSafeties = o.realList("fine_dt_safety", {}, "1",
                                  "optional dt ladder (gfverlet) on the mesh ladder's finest mesh (empty: none)");
  OptionReader out(comm, "", "Results file", record);
  const std::string output = out.text("output", "gradfric_study_fem.h5", "study results file (HDF5)");
  const bool overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  if (helpRequested()) return;
  const auto meshes = parseMeshes(o, "meshes", meshText);
  const auto estimates = parseMeshes(o, "mesh_estimate", estimateText);
  if (meshes.empty()) throw InputError(o.fullName("meshes"), meshText, "at least one mesh");
  o.requireAtLeast("mesh_estimate_steps", estimateSteps, 2);
  for (auto* list : {&safeties, &safetiesOther, &paperSafeties})
    for (double s : *list) o.requireRange("dt_safety", s, 1e-6, 1.0, "0 < safety <= 1");
  for (double f : factors) o.requireRange("penalty_factors", f, 1e-6, 1e6, "1e-6 <= factor <= 1e6");
  o.requireRange("penalty_dt_safety", penaltySafety, 1e-6, 1.0, "0 < safety <= 1");
  o.requireRange("mesh_dt_safety", meshSafety, 1e-6, 1.0, "0 < safety <= 1");
  if (dtSet) throw InputError("-fem_dt", "(set)", "unset: the study sets the step as a fraction of the stable step");
  if (!base.output.empty()) throw InputError("-fem_output", base.output, "unset: the study writes -output");
  if (rank == 0 && access(output.c_str(), F_OK) == 0 && !overwrite)
    throw InputError("-output", output, "a file that does not exist yet (add -output_overwrite to replace it)");
  checkUnusedOptions(comm, {"study_", "plate_", "fem_", "grading_", "output"});
  std::sort(safeties.begin(), safeties.end());
  std::sort(safetiesOther.begin(), safetiesOther.end());
  std::sort(factors.begin(), factors.end());
  std::sort(paperSafeties.begin(), paperSafeties.end());

  base.verbose = false;
  base.dt = 0;
  // Parameters on another mesh: the derived penalty follows the mesh unless the scene set it.
  auto onMesh = [&](const std::array<int, 3>& m) {
    fem::FemParameters q = base;
    q.nx = m[0];
    q.ny = m[1];
    q.nz = m[2];
    if (!knSet) q.kn = 0;
    if (!ktSet) q.kt = knSet ? q.kn : 0;
    q.resolveDerived();
    return q;
  };

  // ---- The ladders. ----
  std::vector<Ladder> ladders;
  auto want = [&](const char* k) { return std::find(knobs.begin(), knobs.end(), k) != knobs.end(); };
  if (want("dt")) {
    for (const auto& name : integrators) {
      Ladder l{"dt_" + name, "dt_safety", "1 (fraction of the stable step)",
               "|mu/mu_ref - 1|, reference: the smallest dt_safety of the first integrator", {}, {}, {}, {}, -1};
      for (double s : name == integrators.front() ? safeties : safetiesOther) {
        fem::FemParameters q = base;
        q.dtSafety = s;
        l.values.push_back(s);
        l.runs.push_back(q);
        l.integrators.push_back(name);
      }
      ladders.push_back(l);
    }
  }
  for (const char* which : {"kn", "kt"}) {
    if (!want(which)) continue;
    Ladder l{which, std::string(which) == "kn" ? "k_n factor" : "k_t factor", "1 (x the default E0/hz)",
             "|mu/mu_ref - 1|, reference: the stiffest penalty", {}, {}, {}, {}, int(factors.size()) - 1};
    for (double f : factors) {
      fem::FemParameters q = base;
      if (which[1] == 'n') q.kn = f * base.kn;
      else q.kt = f * base.kt;
      q.dtSafety = penaltySafety;
      l.values.push_back(f);
      l.runs.push_back(q);
      l.integrators.push_back("gfverlet");
    }
    ladders.push_back(l);
  }
  if (want("mesh")) {
    Ladder l{"mesh", "nx", "1 (nx x nx x nz hexahedra)", "|mu/mu_ref - 1|, reference: the finest mesh", {}, {}, {}, {},
             int(meshes.size()) - 1};
    for (const auto& m : meshes) {
      l.values.push_back(m[0]);
      l.runs.push_back(onMesh(m));
      l.runs.back().dtSafety = meshSafety;
      l.integrators.push_back("gfverlet");
    }
    ladders.push_back(l);
    if (!paperSafeties.empty()) {
      Ladder f{"dt_fine_mesh", "dt_safety", "1 (fraction of the stable step)",
               "|mu/mu_ref - 1|, reference: the smallest dt_safety on the finest mesh", {}, {}, {}, {}, 0};
      for (double s : paperSafeties) {
        fem::FemParameters q = onMesh(meshes.back());
        q.dtSafety = s;
        f.values.push_back(s);
        f.runs.push_back(q);
        f.integrators.push_back("gfverlet");
      }
      ladders.push_back(f);
    }
  }

  std::size_t total = 0;
  for (const auto& l : ladders) total += l.runs.size();
  const std::string loadStart = loadAverage();
  GF_CALL(PetscPrintf(comm, "FEM accuracy-cost study: %zu runs, each on %d rank(s); load average at start %s\n", total,
                      size, loadStart.c_str()));
  const double studyStart = MPI_Wtime();
  // The same run in two ladders (e.g. the default rung of kn and kt) is run once.
  std::vector<std::pair<std::string, Outcome>> done;
  auto key = [](const fem::FemParameters& q, const std::string& integrator) {
    char k[300];
    std::snprintf(k, sizeof k, "%d %d %d %.17g %.17g %.17g %s", q.nx, q.ny, q.nz, q.kn, q.kt, q.dtSafety,
                  integrator.c_str());
    return std::string(k);
  };
  for (auto& l : ladders) {
    l.outcomes.resize(l.runs.size());
    for (std::size_t i = 0; i < l.runs.size(); ++i) {
      const std::string k = key(l.runs[i], l.integrators[i]);
      auto hit = std::find_if(done.begin(), done.end(), [&](const auto& d) { return d.first == k; });
      if (hit != done.end()) {
        l.outcomes[i] = hit->second;
      } else {
        l.outcomes[i] = runOne(comm, l.runs[i], grading, l.integrators[i]);
        done.emplace_back(k, l.outcomes[i]);
      }
      const Outcome& r = l.outcomes[i];
      const auto& q = l.runs[i];
      GF_CALL(PetscPrintf(comm,
                          "  %-14s %-8s %dx%dx%d dt %.4g s (stable %.4g): mu_s %.6f mu_k %.6f%s, %6.0f steps, wall "
                          "%.2f s, cpu %.2f s %s%s\n",
                          l.name.c_str(), formatReal(l.values[i]).c_str(), q.nx, q.ny, q.nz,
                          r.dt, r.stableDt, r.muS, r.muK, r.windowComplete ? "" : " (window incomplete)", r.steps,
                          r.wall, r.cpu, r.failure.empty() ? "" : "FAILED: ", r.failure.c_str()));
    }
  }

  // Meshes too big to run through: a short run gives the time per step; the full run needs the
  // steps of the finest mesh run, scaled by the ratio of the time steps.
  std::vector<std::array<double, 4>> estimateRows;  // nx, ms/step, steps, estimated seconds
  const Ladder* meshLadder = nullptr;
  for (const auto& l : ladders)
    if (l.name == "mesh") meshLadder = &l;
  for (const auto& m : estimates) {
    fem::FemParameters q = onMesh(m);
    q.dtSafety = meshSafety;
    const double dt = q.dtSafety * fem::stableTimeStep(q, grading);
    q.rampTime = 0;
    q.settleTime = 0;
    q.slideTime = double(estimateSteps) * dt;
    q.stopWhenKnown = false;
    GF_CALL_MPI(MPI_Barrier(comm));
    const double w0 = MPI_Wtime();
    fem::PlateModel model(comm, q, grading);
    const double setup = MPI_Wtime() - w0;
    const fem::FemRunResult r = fem::runPlateExperiment(model);
    const double perStep = r.wallSliding / double(std::max(1L, r.steps));
    double steps = NAN;
    if (meshLadder && !meshLadder->outcomes.empty()) {
      const Outcome& fine = meshLadder->outcomes.back();
      steps = fine.steps * fine.dt / dt;
    }
    estimateRows.push_back({double(m[0]), 1e3 * perStep, steps, setup + steps * perStep});
    GF_CALL(PetscPrintf(comm,
                        "  estimate %dx%dx%d: set-up %.1f s, %.2f ms/step over %ld steps (dt %.4g s); a full run needs "
                        "~%.0f steps: ~%.0f s\n",
                        m[0], m[1], m[2], setup, 1e3 * perStep, r.steps, dt, steps, setup + steps * perStep));
  }
  const double studyWall = MPI_Wtime() - studyStart;
  const std::string loadEnd = loadAverage();
  record->add({"study load average (start)", loadStart, "", "/proc/loadavg", OptionOrigin::Derived});
  record->add({"study load average (end)", loadEnd, "", "/proc/loadavg", OptionOrigin::Derived});
  record->add({"study wall seconds", formatReal(studyWall), "s", "whole study", OptionOrigin::Derived});
  GF_CALL(PetscPrintf(comm, "study done in %.1f s; load average at end %s\n", studyWall, loadEnd.c_str()));
  if (rank != 0) return;

  // ---- Errors against the reference rungs, table, file. ----
  const std::string partial = output + ".partial";
  io::H5File file(GF_H5(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)));
  writeText(file, "format", "gradfric-accuracy-study");
  writeText(file, "model", "fem");
  for (const auto& option : record->all()) {
    std::string name = option.name[0] == '-' ? option.name.substr(1) : option.name;
    writeText(file, name, option.value);
  }
  const Ladder* dtReference = nullptr;
  for (const auto& l : ladders)
    if (l.knob == "dt_safety" && l.reference < 0 && !dtReference) dtReference = &l;
  std::printf("\n%-14s %-8s %12s %12s %10s %10s %9s %9s %8s\n", "ladder", "setting", "mu_s rel.err", "mu_k rel.err",
              "mu_s", "mu_k", "wall [s]", "cpu [s]", "steps");
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
      std::printf("%-14s %-8s %12.3e %12.3e %10.6f %10.6f %9.2f %9.2f %8.0f%s\n", l.name.c_str(),
                  formatReal(l.values[i]).c_str(), es[i], ek[i], r.muS, r.muK, r.wall, r.cpu, r.steps,
                  r.failure.empty() ? "" : "  (failed)");
    }
    io::H5Group group(GF_H5(H5Gcreate2(file, l.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
    writeText(group, "knob", l.knob);
    writeText(group, "unit", l.unit);
    writeText(group, "error_meaning", l.meaning);
    writeText(group, "integrator", l.integrators.front());
    writeVector(group, "setting", l.values);
    writeVector(group, "mu_s_error", es);
    writeVector(group, "mu_k_error", ek);
    writeVector(group, "wall_seconds", wall);
    writeVector(group, "cpu_seconds", cpu);
    writeVector(group, "mu_s", muS);
    writeVector(group, "mu_k", muK);
    writeVector(group, "dt", dt);
    writeVector(group, "steps", steps);
    if (l.name == "mesh") {
      // Meshes timed by a short run only (an attribute: plot_accuracy.py reads every group as a ladder).
      std::string text;
      for (const auto& r : estimateRows) {
        char line[200];
        std::snprintf(line, sizeof line, "%snx %g: %.2f ms/step, ~%.0f steps, ~%.0f s", text.empty() ? "" : "; ", r[0],
                      r[1], r[2], r[3]);
        text += line;
      }
      if (!text.empty()) writeText(group, "estimates", text);
    }
  }
  file.reset();
  if (std::rename(partial.c_str(), output.c_str()) != 0) throw std::runtime_error("cannot rename " + partial);
  std::printf("\nstudy results in %s\n", output.c_str());
}

}  // namespace gradfric::study
