// The accuracy-cost study of the spring-block model (include/gradfric/study/sbm_study.hpp), as
// named steps: read the options, plan the file, build the ladders, run them, tabulate the errors,
// save, print.
#include "gradfric/study/sbm_study.hpp"
#include "gradfric/study/study_file.hpp"

#include "gradfric/campaign/realisation_pool.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/run_limits.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>

namespace gradfric::study {

namespace {

struct Study {
  Grading grading;
  sbm::Parameters base;
  sbm::Request request;
  std::vector<std::string> knobs, integrators;
  std::vector<double> dts, sizes;
  int dtRealisations = 3, sizeRealisations = 8, maxRealisations = 32;
  std::uint64_t seed = 1;
  std::string output;
  bool overwrite = false;
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

// One run of the study: a rung of a ladder and a realisation.
struct Task {
  int ladder = 0, rung = 0, realisation = 0;
  sbm::Parameters parameters;
};

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); }

double standardError(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1) / double(v.size()));
}

std::optional<Study> readStudy(MPI_Comm comm, RunParameters* record) {
  Study s;
  s.grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  s.base = sbm::readParameters(comm, record, plate, s.grading);
  s.request = sbm::readRequest(comm, record, s.base);
  if (!helpRequested())  // -pressure_response_select grading: the g of the study's grading, before any work
    (void)selectedFor(s.base.pressureResponse, s.grading, s.base.plate.slidingAngle, "the study's scene");
  s.request.endTime = 0.0;
  s.request.measurement.historyInterval = 1e3;  // the study keeps no histories
  OptionReader o(comm, "study_", "Accuracy-cost study (spring-block model)", record);
  s.knobs = o.choiceList("knobs", {"dt", "N", "R"}, {"dt", "N", "R"},
                         "ladders to run: time step per integrator, lattice size, number of realisations");
  s.integrators = o.choiceList("integrators", {"rk4", "verlet"}, {"rk4", "verlet"}, "integrators of the dt ladder");
  s.dts = o.realList("dt", {1e-9, 3e-9, 1e-8, 3e-8, 1e-7, 3e-7, 1e-6}, "s",
                     "time-step ladder (rungs above an integrator's stability limit are replaced by 0.98 x the limit)");
  const PetscInt dtRealisations = o.integer("dt_realisations", 3, 1, 100000, "1", "realisations (same seeds on every rung) of the dt ladder");
  s.sizes = o.realList("N", {30, 60, 120, 240}, "1", "lattice-size ladder N_b (finest is the reference)");
  const PetscInt sizeRealisations = o.integer("N_realisations", 8, 1, 100000, "1", "realisations per lattice size");
  const PetscInt maxRealisations = o.integer("R_max", 32, 1, 1000000, "1", "sample size of the realisations ladder (R = 1, 2, 4, ... R_max)");
  const PetscInt seed = o.integer("seed", 1, 0, PETSC_MAX_INT, "1", "seed of the realisations' random streams");
  OptionReader out(comm, "", "Results file", record);
  s.output = out.text("output", "gradfric_study.h5", "study results file (HDF5)");
  s.overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  if (helpRequested()) return std::nullopt;
  o.requireAtLeast("dt_realisations", dtRealisations, 1);
  o.requireAtLeast("N_realisations", sizeRealisations, 2);
  o.requireAtLeast("R_max", maxRealisations, 2);
  for (double dt : s.dts) o.requirePositive("dt", dt, "s");
  for (double n : s.sizes)
    if (n < 2 || n > 4096 || n != std::floor(n)) throw InputError(o.fullName("N"), formatReal(n), "whole numbers 2 <= N <= 4096");
  for (double dt : s.dts)  // before any work: a rung of 1e-300 s would never finish
    requireRunLength(record, s.request.maxTime, dt, s.base.automaticTimeStep, o.fullName("dt"), {}, {}, "t_max");
  checkUnusedOptions(comm, {"study_", "plate_", "surface_", "friction_", "sbm_", "grading_", "output"});
  std::sort(s.dts.begin(), s.dts.end());
  s.dtRealisations = int(dtRealisations);
  s.sizeRealisations = int(sizeRealisations);
  s.maxRealisations = int(maxRealisations);
  s.seed = std::uint64_t(seed);
  return s;
}

std::vector<Ladder> buildLadders(const Study& s) {
  std::vector<Ladder> ladders;
  auto want = [&](const char* k) { return std::find(s.knobs.begin(), s.knobs.end(), k) != s.knobs.end(); };
  if (want("dt")) {
    for (const auto& name : s.integrators) {
      sbm::Parameters p = s.base;
      p.integrator = name == "verlet" ? sbm::Integrator::VelocityVerlet : sbm::Integrator::RK4;
      const double limit = sbm::stableTimeStep(p, s.grading);
      Ladder ladder{"dt_" + name, "dt", "s", {}, s.dtRealisations, {}};
      for (double dt : s.dts) ladder.values.push_back(std::min(dt, 0.98 * limit));
      ladder.values.erase(std::unique(ladder.values.begin(), ladder.values.end()), ladder.values.end());
      ladders.push_back(ladder);
    }
  }
  if (want("N")) ladders.push_back({"N", "N_b", "1", s.sizes, s.sizeRealisations, {}});
  if (want("R")) ladders.push_back({"R", "R", "1", {double(s.maxRealisations)}, s.maxRealisations, {}});
  for (auto& ladder : ladders)
    ladder.outcomes.assign(ladder.values.size(), std::vector<Outcome>(ladder.realisations));
  return ladders;
}

std::vector<Task> buildTasks(const Study& s, const std::vector<Ladder>& ladders) {
  std::vector<Task> tasks;
  for (int l = 0; l < int(ladders.size()); ++l) {
    const Ladder& ladder = ladders[l];
    for (int rung = 0; rung < int(ladder.values.size()); ++rung) {
      for (int r = 0; r < ladder.realisations; ++r) {
        Task t{l, rung, r, s.base};
        if (ladder.knob == "dt") {
          t.parameters.integrator = ladder.name == "dt_verlet" ? sbm::Integrator::VelocityVerlet : sbm::Integrator::RK4;
          t.parameters.timeStep = ladder.values[rung];
        } else if (ladder.knob == "N_b") {
          // The shipped defaults for each size: damping and time step follow the lattice.
          t.parameters.blocksPerSide = int(ladder.values[rung]);
          const double scale = double(s.base.blocksPerSide) / t.parameters.blocksPerSide;
          t.parameters.damping = s.base.damping / scale;  // 0.1 sqrt(K_int/m) scales as 1/l
          t.parameters.timeStep = sbm::defaultTimeStep(t.parameters, s.grading);
        }
        tasks.push_back(t);
      }
    }
  }
  return tasks;
}

// Over the ranks by the realisation pool, biggest first so that the ranks finish together; every
// rank ends with every outcome.
void runTasks(MPI_Comm comm, const Study& s, const std::vector<Task>& tasks, std::vector<Ladder>* ladders) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  campaign::PoolPlan plan;
  plan.tasks = static_cast<long>(tasks.size());
  plan.width = 4;  // mu_s, mu_k, wall seconds, steps
  plan.schedule = campaign::Schedule::Static;
  plan.handOutOrder.resize(tasks.size());
  std::iota(plan.handOutOrder.begin(), plan.handOutOrder.end(), 0L);
  auto cost = [&](const Task& t) {
    const double n = double(t.parameters.blocksPerSide) * t.parameters.blocksPerSide;
    const double perStep = t.parameters.integrator == sbm::Integrator::VelocityVerlet ? 0.45 : 1.0;
    return n * perStep / t.parameters.timeStep;
  };
  std::stable_sort(plan.handOutOrder.begin(), plan.handOutOrder.end(),
                   [&](long a, long b) { return cost(tasks[a]) > cost(tasks[b]); });
  plan.failure = [&](long k, int onRank, const std::string& what) {
    return "study run " + (*ladders)[tasks[k].ladder].name + " rung " + std::to_string(tasks[k].rung) +
           " realisation " + std::to_string(tasks[k].realisation) + " failed on rank " + std::to_string(onRank) + ": " +
           what;
  };
  GF_CALL(PetscPrintf(comm, "Accuracy-cost study: %zu runs on %d rank(s)\n", tasks.size(), size));
  const std::vector<double> records = campaign::runRealisationPool(comm, plan, [&](long k) {
    const Task& t = tasks[k];
    const sbm::Result r = sbm::simulate(t.parameters, s.grading, s.request,
                                        StreamKey{s.seed, 0, std::uint32_t(t.realisation)});
    std::printf("  [rank %d] %-9s rung %d realisation %d: dt = %.3g s, N_b = %d: mu_s = %.6f, mu_k = %.6f, %.2f s\n", rank,
                (*ladders)[t.ladder].name.c_str(), t.rung, t.realisation, t.parameters.timeStep,
                t.parameters.blocksPerSide, r.friction.muStatic, r.friction.muKinetic, r.wallSeconds);
    std::fflush(stdout);
    return std::vector<double>{r.friction.muStatic, r.friction.muKinetic, r.wallSeconds, double(r.steps)};
  });
  for (std::size_t k = 0; k < tasks.size(); ++k)
    (*ladders)[tasks[k].ladder].outcomes[tasks[k].rung][tasks[k].realisation] = {
        records[4 * k], records[4 * k + 1], records[4 * k + 2], records[4 * k + 3]};
}

// The errors of one ladder against its reference: the finest dt of the first integrator (same
// seeds: realisation by realisation), the largest lattice (means), or, for R, the statistical
// error of the mean of R realisations from one sample of R_max.
LadderTable errorTable(const Ladder& ladder, const Ladder* dtReference) {
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
  if (ladder.knob == "N_b") {
    for (int rung = 0; rung < rungs; ++rung) {
      errStatic[rung] = std::fabs(muS[rung] / muS[rungs - 1] - 1);
      errKinetic[rung] = std::fabs(muK[rung] / muK[rungs - 1] - 1);
    }
  }
  if (ladder.knob == "R") {
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
  LadderTable table;
  table.name = ladder.name;
  table.texts = {{"knob", ladder.knob},
                 {"unit", ladder.unit},
                 {"error_meaning",
                  ladder.knob == "dt"    ? "max over realisations of |mu/mu_ref - 1|, same seeds, reference: finest dt of the first integrator"
                  : ladder.knob == "N_b" ? "|mean/mean_ref - 1| against the largest lattice (statistical error in *_stderr)"
                                         : "relative standard error of the ensemble mean for R realisations"}};
  table.columns = {{"setting", settings}, {"mu_s_error", errStatic}, {"mu_k_error", errKinetic},
                   {"wall_seconds", wall}, {"mu_s", muS},             {"mu_k", muK}};
  if (ladder.knob != "R") {
    table.columns.emplace_back("mu_s_stderr", seS);
    table.columns.emplace_back("mu_k_stderr", seK);
  }
  return table;
}

std::vector<LadderTable> errorTables(const std::vector<Ladder>& ladders) {
  // The dt ladders share one reference: the finest step of the first integrator (RK4 if run).
  const Ladder* dtReference = nullptr;
  for (const auto& l : ladders)
    if (l.knob == "dt" && !dtReference) dtReference = &l;
  std::vector<LadderTable> tables;
  for (const auto& ladder : ladders) tables.push_back(errorTable(ladder, dtReference));
  return tables;
}

const std::vector<double>& column(const LadderTable& t, const std::string& name) {
  for (const auto& [n, values] : t.columns)
    if (n == name) return values;
  throw std::logic_error("study table without column " + name);
}

void printTables(MPI_Comm comm, const std::vector<LadderTable>& tables, const std::string& output) {
  GF_CALL(PetscPrintf(comm, "\n%-10s %-12s %14s %14s %14s %14s %12s\n", "ladder", "setting", "mu_s rel.err",
                      "mu_k rel.err", "mu_s", "mu_k", "s/realis."));
  for (const auto& t : tables) {
    const auto& settings = column(t, "setting");
    for (std::size_t i = 0; i < settings.size(); ++i)
      GF_CALL(PetscPrintf(comm, "%-10s %-12s %14.3e %14.3e %14.6f %14.6f %12.3f\n", t.name.c_str(),
                          formatReal(settings[i]).c_str(), column(t, "mu_s_error")[i], column(t, "mu_k_error")[i],
                          column(t, "mu_s")[i], column(t, "mu_k")[i], column(t, "wall_seconds")[i]));
  }
  GF_CALL(PetscPrintf(comm, "\nstudy results in %s\n", output.c_str()));
}

}  // namespace

void runSpringBlockStudy(MPI_Comm comm, RunParameters* record) {
  const std::optional<Study> study = readStudy(comm, record);
  if (!study) return;  // -help
  const io::OutputPlan plan = planStudyFile(comm, study->output, study->overwrite);
  std::vector<Ladder> ladders = buildLadders(*study);
  runTasks(comm, *study, buildTasks(*study, ladders), &ladders);
  const std::vector<LadderTable> tables = errorTables(ladders);
  saveStudyFile(comm, plan, {studyAttributes(*record, {}), tables});
  printTables(comm, tables, plan.path());
}

}  // namespace gradfric::study
