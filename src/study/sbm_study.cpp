#include "gradfric/study/sbm_study.hpp"
#include "gradfric/study/study_file.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/run_limits.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/hdf5_handle.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numeric>
#include <unistd.h>

namespace gradfric::study {

namespace {

// One run of the study: a rung of a ladder and a realisation.
struct Task {
  std::string ladder;  // "dt_rk4", "dt_verlet", "N", "R"
  int rung = 0;
  int realisation = 0;
  sbm::Parameters parameters;
};

struct Outcome {
  double muStatic = 0, muKinetic = 0, wall = 0, steps = 0;
};

struct Ladder {
  std::string name, knob, unit;
  std::vector<double> values;  // the setting of each rung
  int realisations = 0;
  std::vector<std::vector<Outcome>> outcomes;  // [rung][realisation]
};

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

double standardError(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1) / double(v.size()));
}

}  // namespace

void runSpringBlockStudy(MPI_Comm comm, RunParameters* record) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));

  const Grading grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  const sbm::Parameters base = sbm::readParameters(comm, record, plate, grading);
  sbm::Request request = sbm::readRequest(comm, record, base);
  request.endTime = 0.0;
  request.measurement.historyInterval = 1e3;  // the study keeps no histories
  OptionReader o(comm, "study_", "Accuracy-cost study (spring-block model)", record);
  const auto knobs = o.choiceList("knobs", {"dt", "N", "R"}, {"dt", "N", "R"},
                                  "ladders to run: time step per integrator, lattice size, number of realisations");
  const auto integrators = o.choiceList("integrators", {"rk4", "verlet"}, {"rk4", "verlet"}, "integrators of the dt ladder");
  auto dts = o.realList("dt", {1e-9, 3e-9, 1e-8, 3e-8, 1e-7, 3e-7, 1e-6}, "s",
                        "time-step ladder (rungs above an integrator's stability limit are replaced by 0.98 x the limit)");
  const PetscInt dtRealisations = o.integer("dt_realisations", 3, 1, 100000, "1", "realisations (same seeds on every rung) of the dt ladder");
  const auto sizes = o.realList("N", {30, 60, 120, 240}, "1", "lattice-size ladder N_b (finest is the reference)");
  const PetscInt sizeRealisations = o.integer("N_realisations", 8, 1, 100000, "1", "realisations per lattice size");
  const PetscInt maxRealisations = o.integer("R_max", 32, 1, 1000000, "1", "sample size of the realisations ladder (R = 1, 2, 4, ... R_max)");
  const PetscInt seed = o.integer("seed", 1, 0, PETSC_MAX_INT, "1", "seed of the realisations' random streams");
  OptionReader out(comm, "", "Results file", record);
  const std::string output = out.text("output", "gradfric_study.h5", "study results file (HDF5)");
  const bool overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  if (helpRequested()) return;
  o.requireAtLeast("dt_realisations", dtRealisations, 1);
  o.requireAtLeast("N_realisations", sizeRealisations, 2);
  o.requireAtLeast("R_max", maxRealisations, 2);
  for (double dt : dts) o.requirePositive("dt", dt, "s");
  for (double n : sizes)
    if (n < 2 || n > 4096 || n != std::floor(n)) throw InputError(o.fullName("N"), formatReal(n), "whole numbers 2 <= N <= 4096");
  for (double dt : dts)  // before any work: a rung of 1e-300 s would never finish
    requireRunLength(record, request.maxTime, dt, base.automaticTimeStep, o.fullName("dt"), {}, {}, "t_max");
  if (access(output.c_str(), F_OK) == 0 && !overwrite)
    throw InputError("-output", output, "a file that does not exist yet (add -output_overwrite to replace it)");
  checkUnusedOptions(comm, {"study_", "plate_", "friction_", "sbm_", "grading_", "output"});
  std::sort(dts.begin(), dts.end());

  // ---- The ladders and their tasks. ----
  std::vector<Ladder> ladders;
  auto want = [&](const char* k) { return std::find(knobs.begin(), knobs.end(), k) != knobs.end(); };
  if (want("dt")) {
    for (const auto& name : integrators) {
      sbm::Parameters p = base;
      p.integrator = name == "verlet" ? sbm::Integrator::VelocityVerlet : sbm::Integrator::RK4;
      const double limit = sbm::stableTimeStep(p, grading);
      Ladder ladder{"dt_" + name, "dt", "s", {}, int(dtRealisations), {}};
      for (double dt : dts) ladder.values.push_back(std::min(dt, 0.98 * limit));
      ladder.values.erase(std::unique(ladder.values.begin(), ladder.values.end()), ladder.values.end());
      ladders.push_back(ladder);
    }
  }
  if (want("N")) ladders.push_back({"N", "N_b", "1", sizes, int(sizeRealisations), {}});
  if (want("R")) ladders.push_back({"R", "R", "1", {double(maxRealisations)}, int(maxRealisations), {}});

  std::vector<Task> tasks;
  for (auto& ladder : ladders) {
    ladder.outcomes.assign(ladder.values.size(), std::vector<Outcome>(ladder.realisations));
    for (int rung = 0; rung < int(ladder.values.size()); ++rung) {
      for (int r = 0; r < ladder.realisations; ++r) {
        Task t{ladder.name, rung, r, base};
        if (ladder.knob == "dt") {
          t.parameters.integrator = ladder.name == "dt_verlet" ? sbm::Integrator::VelocityVerlet : sbm::Integrator::RK4;
          t.parameters.timeStep = ladder.values[rung];
        } else if (ladder.knob == "N_b") {
          // The shipped defaults for each size: damping and time step follow the lattice.
          t.parameters.blocksPerSide = int(ladder.values[rung]);
          const double scale = double(base.blocksPerSide) / t.parameters.blocksPerSide;
          t.parameters.damping = base.damping / scale;  // 0.1 sqrt(K_int/m) scales as 1/l
          t.parameters.timeStep = sbm::defaultTimeStep(t.parameters, grading);
        }
        tasks.push_back(t);
      }
    }
  }

  // ---- Run: round-robin over ranks, biggest first so that the ranks finish together. ----
  std::vector<int> order(tasks.size());
  std::iota(order.begin(), order.end(), 0);
  auto cost = [&](const Task& t) {
    const double n = double(t.parameters.blocksPerSide) * t.parameters.blocksPerSide;
    const double perStep = t.parameters.integrator == sbm::Integrator::VelocityVerlet ? 0.45 : 1.0;
    return n * perStep / t.parameters.timeStep;
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost(tasks[a]) > cost(tasks[b]); });
  std::vector<double> flat(tasks.size() * 4, 0.0);
  GF_CALL(PetscPrintf(comm, "Accuracy-cost study: %zu runs on %d rank(s)\n", tasks.size(), size));
  for (std::size_t k = rank; k < order.size(); k += size) {
    const Task& t = tasks[order[k]];
    const sbm::Result r = sbm::simulate(t.parameters, grading, request,
                                        StreamKey{std::uint64_t(seed), 0, std::uint32_t(t.realisation)});
    double* slot = &flat[4 * order[k]];
    slot[0] = r.friction.muStatic;
    slot[1] = r.friction.muKinetic;
    slot[2] = r.wallSeconds;
    slot[3] = double(r.steps);
    std::printf("  [rank %d] %-9s rung %d realisation %d: dt = %.3g s, N_b = %d: mu_s = %.6f, mu_k = %.6f, %.2f s\n", rank,
                t.ladder.c_str(), t.rung, t.realisation, t.parameters.timeStep, t.parameters.blocksPerSide, r.friction.muStatic,
                r.friction.muKinetic, r.wallSeconds);
    std::fflush(stdout);
  }
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, flat.data(), int(flat.size()), MPI_DOUBLE, MPI_SUM, comm));
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    for (auto& ladder : ladders)
      if (ladder.name == tasks[k].ladder)
        ladder.outcomes[tasks[k].rung][tasks[k].realisation] = {flat[4 * k], flat[4 * k + 1], flat[4 * k + 2], flat[4 * k + 3]};
  }
  if (rank != 0) return;

  // ---- Errors against the finest rung, tables, file. ----
  const std::string partial = output + ".partial";
  io::H5File file(GF_H5(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)));
  writeText(file, "format", "gradfric-accuracy-study");
  for (const auto& option : record->all()) writeText(file, option.name.substr(1), option.value);
  // The dt ladders share one reference: the finest step of the first integrator (RK4 if run).
  const Ladder* dtReference = nullptr;
  for (const auto& l : ladders)
    if (l.knob == "dt" && !dtReference) dtReference = &l;
  std::printf("\n%-10s %-12s %14s %14s %14s %14s %12s\n", "ladder", "setting", "mu_s rel.err", "mu_k rel.err",
              "mu_s", "mu_k", "s/realis.");
  for (const auto& ladder : ladders) {
    const int rungs = int(ladder.values.size());
    std::vector<double> errStatic(rungs), errKinetic(rungs), wall(rungs), muS(rungs), muK(rungs), seS(rungs), seK(rungs);
    std::vector<double> settings = ladder.values;
    for (int rung = 0; rung < rungs; ++rung) {
      std::vector<double> s, k, w;
      for (const auto& o : ladder.outcomes[rung]) {
        s.push_back(o.muStatic);
        k.push_back(o.muKinetic);
        w.push_back(o.wall);
      }
      muS[rung] = mean(s);
      muK[rung] = mean(k);
      seS[rung] = standardError(s);
      seK[rung] = standardError(k);
      wall[rung] = mean(w);
      if (ladder.knob == "dt") {
        // Same seeds on every rung: the error of each realisation against its own reference.
        const auto& ref = dtReference->outcomes[0];
        double es = 0, ek = 0;
        for (int r = 0; r < ladder.realisations; ++r) {
          es = std::max(es, std::fabs(ladder.outcomes[rung][r].muStatic / ref[r].muStatic - 1));
          ek = std::max(ek, std::fabs(ladder.outcomes[rung][r].muKinetic / ref[r].muKinetic - 1));
        }
        errStatic[rung] = es;
        errKinetic[rung] = ek;
      }
    }
    if (ladder.knob == "N_b") {  // against the largest lattice, once every mean is known
      for (int rung = 0; rung < rungs; ++rung) {
        errStatic[rung] = std::fabs(muS[rung] / muS[rungs - 1] - 1);
        errKinetic[rung] = std::fabs(muK[rung] / muK[rungs - 1] - 1);
      }
    }
    if (ladder.knob == "R") {
      // The statistical error of the ensemble mean against R, from one sample of R_max.
      std::vector<double> s, k;
      for (const auto& o : ladder.outcomes[0]) {
        s.push_back(o.muStatic);
        k.push_back(o.muKinetic);
      }
      const double sdS = standardError(s) * std::sqrt(double(s.size())), sdK = standardError(k) * std::sqrt(double(k.size()));
      const double perTask = wall[0];
      settings.clear();
      errStatic.clear();
      errKinetic.clear();
      wall.clear();
      for (int R = 1; R <= ladder.realisations; R *= 2) {
        settings.push_back(R);
        errStatic.push_back(sdS / std::sqrt(double(R)) / mean(s));
        errKinetic.push_back(sdK / std::sqrt(double(R)) / mean(k));
        wall.push_back(R * perTask);
      }
      muS.assign(settings.size(), mean(s));
      muK.assign(settings.size(), mean(k));
    }
    for (std::size_t i = 0; i < settings.size(); ++i)
      std::printf("%-10s %-12s %14.3e %14.3e %14.6f %14.6f %12.3f\n", ladder.name.c_str(), formatReal(settings[i]).c_str(),
                  errStatic[i], errKinetic[i], muS[i], muK[i], wall[i]);
    io::H5Group group(GF_H5(H5Gcreate2(file, ladder.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)));
    writeText(group, "knob", ladder.knob);
    writeText(group, "unit", ladder.unit);
    writeText(group, "error_meaning",
              ladder.knob == "dt"    ? "max over realisations of |mu/mu_ref - 1|, same seeds, reference: finest dt of the first integrator"
              : ladder.knob == "N_b" ? "|mean/mean_ref - 1| against the largest lattice (statistical error in *_stderr)"
                                     : "relative standard error of the ensemble mean for R realisations");
    writeVector(group, "setting", settings);
    writeVector(group, "mu_s_error", errStatic);
    writeVector(group, "mu_k_error", errKinetic);
    writeVector(group, "wall_seconds", wall);
    writeVector(group, "mu_s", muS);
    writeVector(group, "mu_k", muK);
    if (ladder.knob != "R") {
      writeVector(group, "mu_s_stderr", seS);
      writeVector(group, "mu_k_stderr", seK);
    }
  }
  file.reset();
  if (std::rename(partial.c_str(), output.c_str()) != 0) throw std::runtime_error("cannot rename " + partial);
  std::printf("\nstudy results in %s\n", output.c_str());
}

}  // namespace gradfric::study
