// Running the FEM study's ladders and estimates (src/study/fem_study_steps.hpp).
#include "fem_study_steps.hpp"

#include <petscsection.h>
#include <petscsf.h>

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/simulation.hpp"

#include <petscsys.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace gradfric::study::fem_study {

namespace {

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

// The ladder's integrator as the run's parameter (createPlateTS sets it before TSSetFromOptions).
fem::FemParameters withIntegrator(fem::FemParameters q, const std::string& name) {
  q.integrator = name == "rk4" ? "rk" : name;
  q.rkScheme = name == "rk4" ? "4" : "";
  return q;
}

Outcome runOne(MPI_Comm comm, const fem::FemParameters& ladderRun, const Grading& grading, const std::string& integrator) {
  const fem::FemParameters q = withIntegrator(ladderRun, integrator);
  Outcome out;
  out.stableDt = fem::stableTimeStep(q, grading);
  out.dt = q.dt.value_or(q.dtSafety * out.stableDt);
  GF_CALL_MPI(MPI_Barrier(comm));
  const double w0 = MPI_Wtime(), c0 = cpuSeconds();
  try {
    fem::PlateModel model(comm, q, grading);
    const fem::FemRunResult r = fem::runPlateExperiment(model);
    out.muS = r.friction.muStatic;
    out.muK = r.friction.muKinetic;
    out.steps = double(r.steps);
    out.dt = r.dt;
    out.stableDt = r.stableDt;
    out.windowComplete = r.friction.kineticComplete;
  } catch (const std::exception& e) {
    // Every rank sees the same collective monitor values, so every rank lands here.
    out.failure = e.what();
  }
  out.wall = MPI_Wtime() - w0;
  out.cpu = cpuSeconds() - c0;
  return out;
}

void printRun(MPI_Comm comm, const Ladder& l, std::size_t i) {
  const Outcome& r = l.outcomes[i];
  const auto& q = l.runs[i];
  GF_CALL(PetscPrintf(comm,
                      "  %-14s %-8s %dx%dx%d dt %.4g s (stable %.4g): mu_s %.6f mu_k %.6f%s, %6.0f steps, wall "
                      "%.2f s, cpu %.2f s %s%s\n",
                      l.name.c_str(), formatReal(l.values[i]).c_str(), q.nx, q.ny, q.nz, r.dt, r.stableDt, r.muS,
                      r.muK, r.windowComplete ? "" : " (window incomplete)", r.steps, r.wall, r.cpu,
                      r.failure.empty() ? "" : "FAILED: ", r.failure.c_str()));
}

}  // namespace

StudyTimer startStudy(MPI_Comm comm, const std::vector<Ladder>& ladders) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  std::size_t total = 0;
  for (const auto& l : ladders) total += l.runs.size();
  StudyTimer timer{loadAverage(), MPI_Wtime()};
  GF_CALL(PetscPrintf(comm, "FEM accuracy-cost study: %zu runs, each on %d rank(s); load average at start %s\n", total,
                      size, timer.loadStart.c_str()));
  return timer;
}

void finishStudy(MPI_Comm comm, const StudyTimer& timer, RunParameters* record) {
  const double studyWall = MPI_Wtime() - timer.start;
  const std::string loadEnd = loadAverage();
  record->add({"study load average (start)", timer.loadStart, "", "/proc/loadavg", OptionOrigin::Derived});
  record->add({"study load average (end)", loadEnd, "", "/proc/loadavg", OptionOrigin::Derived});
  record->add({"study wall seconds", formatReal(studyWall), "s", "whole study", OptionOrigin::Derived});
  GF_CALL(PetscPrintf(comm, "study done in %.1f s; load average at end %s\n", studyWall, loadEnd.c_str()));
}

void runLadders(MPI_Comm comm, const Study& study, std::vector<Ladder>* ladders) {
  // The same run in two ladders (e.g. the default rung of kn and kt) is run once.
  std::vector<std::pair<std::string, Outcome>> done;
  auto key = [](const fem::FemParameters& q, const std::string& integrator) {
    char k[300];
    std::snprintf(k, sizeof k, "%d %d %d %.17g %.17g %.17g %s", q.nx, q.ny, q.nz, q.kn, q.kt, q.dtSafety,
                  integrator.c_str());
    return std::string(k);
  };
  for (auto& l : *ladders) {
    l.outcomes.resize(l.runs.size());
    for (std::size_t i = 0; i < l.runs.size(); ++i) {
      const std::string k = key(l.runs[i], l.integrators[i]);
      auto hit = std::find_if(done.begin(), done.end(), [&](const auto& d) { return d.first == k; });
      if (hit != done.end()) {
        l.outcomes[i] = hit->second;
      } else {
        l.outcomes[i] = runOne(comm, l.runs[i], study.grading, l.integrators[i]);
        done.emplace_back(k, l.outcomes[i]);
      }
      printRun(comm, l, i);
    }
  }
}

// Meshes too big to run through: a short run gives the time per step; the full run needs the
// steps of the finest mesh run, scaled by the ratio of the time steps.
std::vector<Estimate> runEstimates(MPI_Comm comm, const Study& study, const std::vector<Ladder>& ladders) {
  std::vector<Estimate> rows;
  const Ladder* meshLadder = nullptr;
  for (const auto& l : ladders)
    if (l.name == "mesh") meshLadder = &l;
  for (const auto& m : study.estimates) {
    fem::FemParameters q = study.onMesh(m);
    q.dtSafety = study.meshSafety;
    const double dt = q.dtSafety * fem::stableTimeStep(q, study.grading);
    q.rampTime = 0;
    q.settleTime = 0;
    q.slideTime = double(study.estimateSteps) * dt;
    q.stopWhenKnown = false;
    GF_CALL_MPI(MPI_Barrier(comm));
    const double w0 = MPI_Wtime();
    fem::PlateModel model(comm, q, study.grading);
    const double setup = MPI_Wtime() - w0;
    const fem::FemRunResult r = fem::runPlateExperiment(model);
    const double perStep = r.wallSliding / double(std::max(1L, r.steps));
    double steps = NAN;
    if (meshLadder && !meshLadder->outcomes.empty()) {
      const Outcome& fine = meshLadder->outcomes.back();
      steps = fine.steps * fine.dt / dt;
    }
    rows.push_back({double(m[0]), 1e3 * perStep, steps, setup + steps * perStep});
    GF_CALL(PetscPrintf(comm,
                        "  estimate %dx%dx%d: set-up %.1f s, %.2f ms/step over %ld steps (dt %.4g s); a full run needs "
                        "~%.0f steps: ~%.0f s\n",
                        m[0], m[1], m[2], setup, 1e3 * perStep, r.steps, dt, steps, setup + steps * perStep));
  }
  return rows;
}

}  // namespace gradfric::study::fem_study
