// The spring-block scene: options, sweep, tasks over the ranks, one parallel HDF5 results file,
// statistics. See docs/ensemble.md.
#include "gradfric/ensemble/scene_runner.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/random_stream.hpp"
#include "gradfric/ensemble/scheduler.hpp"
#include "gradfric/ensemble/statistics.hpp"
#include "gradfric/ensemble/sweep.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <petsclog.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cerrno>
#include <cstring>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace gradfric::ensemble {

namespace {

// Options that steer one run but not its results: kept out of /scene (stored under /run), so a
// resumed or re-ranked run of the same scene writes the same /scene.
const std::set<std::string> kRunControl = {"-output",          "-output_overwrite",    "-ensemble_resume",
                                           "-ensemble_monitor", "-ensemble_schedule",   "-ensemble_abort_after",
                                           "-ensemble_dry_run"};

struct LogEvents {
  PetscLogEvent task = 0, write = 0, statistics = 0;
};

const LogEvents& logEvents() {
  static LogEvents events = [] {
    LogEvents e;
    PetscClassId id;
    GF_CALL(PetscClassIdRegister("Ensemble", &id));
    GF_CALL(PetscLogEventRegister("EnsTask", id, &e.task));
    GF_CALL(PetscLogEventRegister("EnsH5Write", id, &e.write));
    GF_CALL(PetscLogEventRegister("EnsStatistics", id, &e.statistics));
    return e;
  }();
  return events;
}

std::string hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = static_cast<long>(seconds + 0.5);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buffer;
}

std::string pointLabel(const Sweep& sweep, int p) {
  const SweepPoint& q = sweep.points[p];
  std::ostringstream out;
  bool first = true;
  auto add = [&](const std::string& text) {
    out << (first ? "" : ", ") << text;
    first = false;
  };
  for (const auto& axis : sweep.axes) {
    if (axis == "delta") add("Delta=" + formatReal(q.delta));
    if (axis == "theta") add("theta=" + formatReal(q.theta));
    if (axis == "sigma") add("sigma=" + formatReal(q.sigma));
    if (axis == "property") add("property=" + q.property);
    if (axis == "profile") add("profile=" + q.profile);
  }
  return first ? "single point" : out.str();
}

// The largest modulus factor a point reaches: the stiffest band sets the stable time step.
double stiffestFactor(const Grading& g) {
  double largest = 1.0;
  if (!g.gradesModulus()) return largest;
  for (int b = 0; b < g.bands; ++b) largest = std::max(largest, g.bandFactor(b));
  return largest;
}

enum class FileMode { Fresh, Resume };

struct OutputPlan {
  FileMode mode = FileMode::Fresh;
  std::string finalPath;
  std::string workPath;  // where this run writes: <output>.partial, or the final file on resume
};

std::string parentDirectory(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

bool exists(const std::string& path) { return access(path.c_str(), F_OK) == 0; }

// Decided on rank 0 (file system checks), broadcast, and thrown on every rank alike.
OutputPlan planOutput(MPI_Comm comm, const std::string& output, bool overwrite, bool resume) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  OutputPlan plan;
  plan.finalPath = output;
  const std::string partial = output + ".partial";
  std::string error;
  int mode = 0;
  if (rank == 0) {
    const std::string dir = parentDirectory(output);
    if (output.empty()) {
      error = InputError("-output", "(empty)", "a file path").what();
    } else if (access(dir.c_str(), W_OK | X_OK) != 0) {
      error = InputError("-output", output, "a path in an existing, writable folder (" + dir + " is not)").what();
    } else if (resume && overwrite) {
      error = "conflicting options: -ensemble_resume continues " + output +
              ", -output_overwrite replaces it; give one of them";
    } else if (overwrite) {
      std::remove(output.c_str());
      std::remove(partial.c_str());
      mode = 0;
    } else if (resume) {
      if (exists(partial)) {
        mode = 1;  // continue the interrupted run
      } else if (exists(output)) {
        mode = 2;  // a finished file: checked and its statistics recomputed
      } else {
        mode = 0;  // nothing to resume: a fresh run (so a job script can always pass -ensemble_resume)
      }
      if (mode && !io::isHdf5File(mode == 1 ? partial : output))
        error = "cannot resume: " + (mode == 1 ? partial : output) +
                " is not an HDF5 file (start again with -output_overwrite)";
    } else if (exists(output)) {
      error = InputError("-output", output,
                         "a file that does not exist yet (it does: add -output_overwrite to replace it, or "
                         "-ensemble_resume to continue it)")
                  .what();
    } else if (exists(partial)) {
      error = InputError("-output", output,
                         "a path without an interrupted run (" + partial +
                             " exists: add -ensemble_resume to continue it, or -output_overwrite to start again)")
                  .what();
    } else if (access(dir.c_str(), W_OK) != 0) {
      error = InputError("-output", output, "a writable folder").what();
    }
  }
  int length = static_cast<int>(error.size());
  GF_CALL_MPI(MPI_Bcast(&length, 1, MPI_INT, 0, comm));
  error.resize(length);
  if (length > 0) GF_CALL_MPI(MPI_Bcast(error.data(), length, MPI_CHAR, 0, comm));
  if (!error.empty()) throw InputError(error);
  GF_CALL_MPI(MPI_Bcast(&mode, 1, MPI_INT, 0, comm));
  plan.mode = mode == 0 ? FileMode::Fresh : FileMode::Resume;
  plan.workPath = mode == 2 ? output : partial;
  return plan;
}

std::string stripDash(const std::string& name) { return name.rfind('-', 0) == 0 ? name.substr(1) : name; }

const char* originText(OptionOrigin origin) {
  switch (origin) {
    case OptionOrigin::User: return "set";
    case OptionOrigin::Derived: return "derived";
    default: return "default";
  }
}

// Upper bound of the number of mu(t) samples one task records (sbm::simulate samples at t = 0
// and then every history interval, at most once per step, and stops by t_max or t_end).
int historyCapacity(const sbm::Parameters& p, const sbm::Request& q) {
  double duration = q.maxTime;
  if (q.endTime > 0) duration = std::min(duration, q.endTime);
  const double dt = p.timeStep;
  const double steps = std::ceil(duration / dt) + 2.0;
  double samples = steps;
  if (q.measurement.historyInterval > dt) samples = std::min(samples, std::floor(duration / q.measurement.historyInterval) + 3.0);
  if (samples > 5e7) throw InputError("-friction_history_interval", formatReal(q.measurement.historyInterval),
                                      "an interval giving at most 5e7 mu(t) samples per realisation up to t_max");
  return static_cast<int>(samples) + 2;
}

void printStatistics(MPI_Comm comm, const Sweep& sweep, int realisations, const std::vector<PointStatistics>& stats,
                     bool kinetic, bool paired) {
  if (sweep.points.size() == 1 && realisations == 1) {
    const auto& s = stats[0];
    GF_CALL(PetscPrintf(comm, "\nResult: mu_s = %.6f, mu_k = %.6f%s\n", s.muStatic.mean, s.muKinetic.mean,
                        s.peaksUnconfirmed ? "  (peak NOT confirmed before t_max: mu_s is the maximum reached)" : ""));
    return;
  }
  auto table = [&](const char* title, bool isStatic) {
    GF_CALL(PetscPrintf(comm, "\n%s over %d realisation(s) per point (95%% CI: Student t):\n", title, realisations));
    GF_CALL(PetscPrintf(comm, "  %-5s %-32s %4s %10s %10s %10s %23s %19s\n", "point", "sweep", "R", "mean", "std",
                        "std err", "95% CI", "rel. var. [%]"));
    for (size_t p = 0; p < stats.size(); ++p) {
      const Summary& s = isStatic ? stats[p].muStatic : stats[p].muKinetic;
      const RelativeVariation& v = isStatic ? stats[p].muStaticRelative : stats[p].muKineticRelative;
      char ci[64], rel[64];
      std::snprintf(ci, sizeof ci, "[%.5f, %.5f]", s.ciLow, s.ciHigh);
      if (std::isfinite(v.value))
        std::snprintf(rel, sizeof rel, "%+7.3f +- %.3f", 100 * v.value, std::isfinite(v.error) ? 100 * v.error : 0.0);
      else
        std::snprintf(rel, sizeof rel, "%s", "(no reference)");
      GF_CALL(PetscPrintf(comm, "  %-5zu %-32s %4d %10.6f %10.6f %10.6f %23s %19s%s\n", p,
                          pointLabel(sweep, static_cast<int>(p)).c_str(), s.count, s.mean, s.stdDev, s.stdError, ci,
                          rel, isStatic && stats[p].peaksUnconfirmed ? "  (unconfirmed peaks)" : ""));
    }
  };
  table("Global static friction mu_s", true);
  if (kinetic) table("Global kinetic friction mu_k", false);
  GF_CALL(PetscPrintf(comm,
                      "  rel. var. = (mu - mu_0)/mu_0 against the non-graded point of the same angle and dispersion,"
                      " +- %s\n",
                      paired ? "the error of the paired differences (common random numbers)"
                             : "the error propagated from both standard errors"));
}

}  // namespace

void runSpringBlockScene(MPI_Comm comm, RunParameters* record) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  const auto& events = logEvents();

  // ---- Options: everything is read and checked before any work. ----
  const Grading baseGrading = readGrading(comm, record);
  OptionReader ens(comm, "ensemble_", "Ensemble of spring-block realisations", record);
  const PetscInt realisations =
      ens.integer("realisations", 1, 1, 10000000, "1", "realisations R per sweep point (new local friction draws each)");
  const PetscInt seed = ens.integer("seed", 1, 0, PETSC_MAX_INT, "1", "scene seed: a task's random stream is (seed, point, realisation)");
  SweepLists lists;
  lists.delta = ens.realList("delta", {}, "1", "sweep of the grading amplitude Delta (empty: -grading_delta alone)");
  lists.theta = ens.realList("theta", {}, "degree", "sweep of the sliding angle (empty: -sbm_theta alone)");
  lists.sigma = ens.realList("sigma", {}, "1",
                             "sweep of the relative dispersion, sets sigma_s and sigma_k (empty: -sbm_sigma_s/_k)");
  lists.property = ens.choiceList("property", {}, {"E", "friction", "both"},
                                  "sweep of the graded property (empty: -grading_property alone)");
  lists.profile = ens.choiceList("profile", {}, {"none", "linear", "triangular"},
                                 "sweep of the grading profile (empty: -grading_profile alone)");
  const bool commonStreams = ens.flag(
      "common_streams", false,
      "common random numbers: realisation r of every sweep point draws from the stream (seed, 0, r); the "
      "relative variations then use paired errors");
  const bool history = ens.flag("history", true, "store the mu(t) history of every realisation");
  const bool frictionFields = ens.flag(
      "friction_fields", false,
      "store every realisation's local mu_s,i and mu_k,i (2 N_b^2 values a task; they follow from the seed anyway)");
  int interactive = rank == 0 ? isatty(STDOUT_FILENO) : 0;
  GF_CALL_MPI(MPI_Bcast(&interactive, 1, MPI_INT, 0, comm));
  const bool monitor =
      ens.flag("monitor", interactive != 0, "print a progress line per finished task (default: on for a terminal)");
  const bool resume = ens.flag("resume", false, "continue an interrupted run of the same scene (skips finished tasks)");
  const std::string scheduleName = ens.choice("schedule", "dynamic", {"dynamic", "static"},
                                              "task distribution: shared counter (one-sided MPI) or round robin");
  const bool dryRun = ens.flag("dry_run", false, "check the scene and print the plan, run nothing, write nothing");
  const PetscInt abortAfter = ens.integer(
      "abort_after", 0, 0, PETSC_MAX_INT, "1",
      "testing only: every rank exits abruptly (no close, no finalize) once this many tasks finished (0: never)");
  OptionReader out(comm, "", "Results file", record);
  const std::string output = out.text("output", "gradfric_sbm.h5", "results file (parallel HDF5; see docs/ensemble.md)");
  const bool overwrite = out.flag("output_overwrite", false, "replace an existing results file");

  for (double d : lists.delta)  // before the stable time step is computed from the sweep
    if (!(std::fabs(d) < 1.0)) throw InputError(ens.fullName("delta"), formatReal(d), "values with |Delta| < 1");
  // The sweep (theta and sigma of the base point are filled in once -sbm_* is read).
  SweepPoint base;
  base.delta = baseGrading.delta;
  base.property = toString(baseGrading.property);
  base.profile = toString(baseGrading.profile);
  Sweep sweep = buildSweep(lists, base);
  // The stiffest point sets the stable time step: one dt for the whole sweep.
  Grading stiffest = baseGrading;
  double stiffestValue = stiffestFactor(baseGrading);
  for (const auto& point : sweep.points) {
    const Grading g = gradingOf(point, baseGrading.bands);
    if (stiffestFactor(g) > stiffestValue) {
      stiffestValue = stiffestFactor(g);
      stiffest = g;
    }
  }
  const Plate plate = readPlate(comm, record);
  const sbm::Parameters parameters = sbm::readParameters(comm, record, plate, stiffest);
  const sbm::Request request = sbm::readRequest(comm, record, parameters);
  if (helpRequested()) return;
  ens.requireAtLeast("realisations", realisations, 1);
  ens.requireAtLeast("seed", seed, 0);
  ens.requireAtLeast("abort_after", abortAfter, 0);
  for (double d : lists.delta)
    if (!(std::fabs(d) < 1.0)) throw InputError(ens.fullName("delta"), formatReal(d), "values with |Delta| < 1");
  for (double t : lists.theta)
    if (!std::isfinite(t)) throw InputError(ens.fullName("theta"), formatReal(t), "finite angles [degree]");
  for (double s : lists.sigma) ens.requireRange("sigma", s, 0.0, 0.5, "values with 0 <= sigma <= 0.5");
  const bool anyProfile = baseGrading.profile != GradingProfile::None ||
                          std::any_of(lists.profile.begin(), lists.profile.end(), [](auto& p) { return p != "none"; });
  if (!lists.delta.empty() && !anyProfile)
    throw InputError(ens.fullName("delta"), "(a list)",
                     "only with a grading profile: set -grading_profile linear or triangular (it is none)");
  if (!lists.property.empty() && !anyProfile)
    throw InputError(ens.fullName("property"), "(a list)",
                     "only with a grading profile: set -grading_profile linear or triangular (it is none)");

  checkUnusedOptions(comm, {"ensemble_", "plate_", "friction_", "sbm_", "grading_", "output"});

  base.theta = parameters.plate.slidingAngle;
  base.sigma = parameters.sigmaStatic;
  base.sigmaKinetic = parameters.sigmaKinetic;
  sweep = buildSweep(lists, base);
  const int P = static_cast<int>(sweep.points.size());
  const int R = static_cast<int>(realisations);
  if (static_cast<double>(P) * R > 2e9) throw InputError("too many tasks: sweep points x realisations > 2e9");

  io::EnsembleLayout layout;
  layout.points = P;
  layout.realisations = R;
  layout.historyCapacity = history ? historyCapacity(parameters, request) : 0;
  layout.mapSide = parameters.blocksPerSide;
  layout.firstSlipMap = request.measurement.firstSlipMap;
  layout.frictionFields = frictionFields;
  layout.snapshotTimes = request.snapshotTimes;
  layout.statisticsReal = {"mu_s_mean",      "mu_s_std",     "mu_s_stderr",         "mu_s_ci95_low",
                           "mu_s_ci95_high", "mu_s_relative", "mu_s_relative_error", "mu_k_mean",
                           "mu_k_std",       "mu_k_stderr",   "mu_k_ci95_low",       "mu_k_ci95_high",
                           "mu_k_relative",  "mu_k_relative_error"};
  layout.statisticsInteger = {"finished", "mu_s_count", "mu_k_count", "peaks_unconfirmed"};
  {
    const double bytes = static_cast<double>(P) * R *
                         (4.0 * layout.historyCapacity +  // time, mu, force_x, force_y
                          (layout.firstSlipMap ? 1.0 : 0.0) * layout.mapSide * layout.mapSide +
                          (layout.frictionFields ? 2.0 : 0.0) * layout.mapSide * layout.mapSide +
                          request.snapshotTimes.size() * (1.0 + layout.mapSide * layout.mapSide)) *
                         8.0;
    if (bytes > 64e9)
      throw InputError("results file would need " + formatReal(bytes / 1e9) +
                       " GB: store fewer observables (-friction_observables, -sbm_snapshot_times), a coarser "
                       "-friction_history_interval or -ensemble_history false");
  }

  io::SweepTable table;
  table.axes = sweep.axes;
  for (const auto& q : sweep.points) {
    table.delta.push_back(q.delta);
    table.theta.push_back(q.theta);
    table.sigma.push_back(q.sigma);
    table.sigmaKinetic.push_back(q.sigmaKinetic);
    table.property.push_back(q.property);
    table.profile.push_back(q.profile);
  }
  table.referencePoint = sweep.reference;
  for (const auto& q : sweep.points) {  // the property fields each point uses (results file /properties)
    const sbm::ColumnProperties c = sbm::columnProperties(parameters, gradingOf(q, baseGrading.bands));
    table.modulus.insert(table.modulus.end(), c.modulus.begin(), c.modulus.end());
    table.muStatic.insert(table.muStatic.end(), c.muStatic.begin(), c.muStatic.end());
    table.muKinetic.insert(table.muKinetic.end(), c.muKinetic.begin(), c.muKinetic.end());
  }

  std::vector<io::Attribute> scene, runAttributes;
  for (const auto& o : record->all()) {
    io::Attribute a{stripDash(o.name), o.value, o.unit, originText(o.origin)};
    (kRunControl.count(o.name) ? runAttributes : scene).push_back(a);
  }

  // ---- What this run does. ----
  record->print(comm, "gradfric spring-block scene: resolved parameters");
  GF_CALL(PetscPrintf(comm, "Active effects:\n"));
  {
    // The effects of the most strongly graded point (the sweep line below lists the others).
    Grading shown = baseGrading;
    sbm::Parameters shownParameters = parameters;
    double largest = -1.0;
    for (const auto& q : sweep.points)
      if (q.graded() && std::fabs(q.delta) > largest) {
        largest = std::fabs(q.delta);
        shown = gradingOf(q, baseGrading.bands);
        shownParameters.plate.slidingAngle = q.theta;
        shownParameters.sigmaStatic = q.sigma;
        shownParameters.sigmaKinetic = q.sigmaKinetic;
      }
    if (largest < 0 && !sweep.points.empty()) {
      shown = gradingOf(sweep.points[0], baseGrading.bands);
      shownParameters.plate.slidingAngle = sweep.points[0].theta;
      shownParameters.sigmaStatic = sweep.points[0].sigma;
      shownParameters.sigmaKinetic = sweep.points[0].sigmaKinetic;
    }
    if (P > 1) GF_CALL(PetscPrintf(comm, "  (for the sweep point with the strongest grading)\n"));
    for (const auto& e : sbm::activeEffects(shownParameters, shown, request))
      GF_CALL(PetscPrintf(comm, "  - %s\n", e.c_str()));
  }
  {
    std::string axes;
    for (const auto& a : sweep.axes) axes += (axes.empty() ? "" : " x ") + a;
    GF_CALL(PetscPrintf(comm, "  - sweep: %s (%d point%s) x %d realisation%s = %d task%s on %d rank%s, %s schedule\n",
                        axes.empty() ? "none" : axes.c_str(), P, P == 1 ? "" : "s", R, R == 1 ? "" : "s", P * R,
                        P * R == 1 ? "" : "s", size, size == 1 ? "" : "s", scheduleName.c_str()));
    if (stiffestValue > 1.0)
      GF_CALL(PetscPrintf(comm, "  - one time step for the whole sweep, from its stiffest band (E x %g)\n",
                          stiffestValue));
    GF_CALL(PetscPrintf(comm, "  - stored: mu_s, mu_k per realisation%s%s%s\n",
                        history ? ", mu(t) histories" : "", request.measurement.firstSlipMap ? ", first-slip maps" : "",
                        request.snapshotTimes.empty() ? "" : ", sigma_x/p snapshots"));
  }

  if (dryRun) {
    GF_CALL(PetscPrintf(comm, "Dry run (-ensemble_dry_run): scene checked, %d task(s) planned, nothing run or written\n",
                        P * R));
    return;
  }
  const OutputPlan plan = planOutput(comm, output, overwrite, resume);

  // ---- The results file. ----
  io::ResultsFile file = [&] {
    if (plan.mode == FileMode::Fresh) {
      GF_CALL(PetscPrintf(comm, "Writing %s (renamed to %s when the run completes)\n", plan.workPath.c_str(),
                          plan.finalPath.c_str()));
      return io::ResultsFile::create(comm, plan.workPath, layout, table, scene);
    }
    GF_CALL(PetscPrintf(comm, "Resuming %s\n", plan.workPath.c_str()));
    io::ResultsFile f = [&] {
      try {
        return io::ResultsFile::open(comm, plan.workPath);
      } catch (const io::Hdf5Error& e) {
        throw InputError("cannot resume " + plan.workPath + ": " + e.what() +
                         " (start again with -output_overwrite)");
      }
    }();
    // The scene must be the one the file was started with.
    std::string differences;
    std::vector<io::Attribute> stored = f.sceneAttributes();
    auto findStored = [&](const std::string& name) -> const io::Attribute* {
      for (const auto& a : stored)
        if (a.name == name) return &a;
      return nullptr;
    };
    for (const auto& a : scene) {
      const io::Attribute* s = findStored(a.name);
      if (!s) differences += "\n  -" + a.name + " = " + a.value + " (not in the file)";
      else if (s->value != a.value) differences += "\n  -" + a.name + ": file " + s->value + ", now " + a.value;
    }
    for (const auto& s : stored) {
      bool found = false;
      for (const auto& a : scene) found = found || a.name == s.name;
      if (!found) differences += "\n  -" + s.name + " = " + s.value + " (in the file only)";
    }
    const auto& l = f.layout();
    if (l.points != P || l.realisations != R || l.historyCapacity != layout.historyCapacity ||
        l.mapSide != layout.mapSide || l.firstSlipMap != layout.firstSlipMap || l.frictionFields != layout.frictionFields ||
        l.snapshotTimes.size() != layout.snapshotTimes.size())
      differences += "\n  layout (points, realisations, history capacity or maps)";
    if (!differences.empty())
      throw InputError("cannot resume " + plan.workPath + ": the scene differs from the one it was started with" +
                       " (run that scene, or start again with -output_overwrite):" + differences);
    return f;
  }();
  file.setRunAttributes(runAttributes);
  file.setProvenance(io::collectProvenance(comm));  // version, command line, options files, date, ranks

  std::vector<unsigned char> finished;
  {
    auto flags = file.finishedTasks();
    finished.assign(flags.begin(), flags.end());
  }
  const std::vector<Task> tasks = pendingTasks(sweep, R, finished);
  const long alreadyDone = static_cast<long>(P) * R - static_cast<long>(tasks.size());
  if (plan.mode == FileMode::Resume)
    GF_CALL(PetscPrintf(comm, "%ld of %d tasks already finished; running the other %zu\n", alreadyDone, P * R,
                        tasks.size()));

  // Per-point model inputs.
  std::vector<sbm::Parameters> pointParameters(P, parameters);
  std::vector<Grading> pointGrading(P);
  for (int p = 0; p < P; ++p) {
    pointParameters[p].plate.slidingAngle = sweep.points[p].theta;
    pointParameters[p].sigmaStatic = sweep.points[p].sigma;
    pointParameters[p].sigmaKinetic = sweep.points[p].sigmaKinetic;
    pointGrading[p] = gradingOf(sweep.points[p], baseGrading.bands);
  }

  // ---- The tasks. ----
  std::string failure;
  long finishedHere = 0;
  double taskSecondsHere = 0.0;
  const auto start = std::chrono::steady_clock::now();
  {
    TaskCounter counter(comm, scheduleName == "dynamic" ? Schedule::Dynamic : Schedule::Static);
    auto abortIfDue = [&](long finishedOverall) {
      if (abortAfter <= 0 || finishedOverall < abortAfter) return;
      std::printf("ensemble: -ensemble_abort_after %ld reached: rank %d exits abruptly (test of resume)\n",
                  static_cast<long>(abortAfter), rank);
      std::fflush(stdout);
      std::_Exit(86);
    };
    for (;;) {
      if (abortAfter > 0) abortIfDue(counter.finishedSoFar());
      const long index = counter.next();
      if (index >= static_cast<long>(tasks.size())) break;
      const Task task = tasks[index];
      try {
        const StreamKey key{static_cast<std::uint64_t>(seed),
                            static_cast<std::uint32_t>(commonStreams ? 0 : task.point),
                            static_cast<std::uint32_t>(task.realisation)};
        GF_CALL(PetscLogEventBegin(events.task, 0, 0, 0, 0));
        const auto taskStart = std::chrono::steady_clock::now();
        sbm::Result result = sbm::simulate(pointParameters[task.point], pointGrading[task.point], request, key);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - taskStart).count();
        GF_CALL(PetscLogEventEnd(events.task, 0, 0, 0, 0));

        io::TaskOutput o;
        o.point = task.point;
        o.realisation = task.realisation;
        o.muStatic = result.friction.muStatic;
        o.muKinetic = result.friction.muKinetic;
        o.peakTime = result.friction.peakTime;
        o.endTime = result.endTime;
        o.peakConfirmed = result.friction.peakConfirmed;
        o.steps = result.steps;
        o.redrawnBlocks = result.redrawnBlocks;
        if (history) {
          o.time = std::move(result.friction.time);
          o.mu = std::move(result.friction.mu);
          o.forceX = std::move(result.friction.forceX);
          o.forceY = std::move(result.friction.forceY);
        }
        o.firstSlipTime = std::move(result.firstSlipTime);
        if (frictionFields) {  // the same draw as the run's (a pure function of the stream key)
          const auto& q = pointParameters[task.point];
          const sbm::FrictionField field = sbm::buildFriction(q, pointGrading[task.point], key);
          const int nb = q.blocksPerSide;
          const double normal = q.normalForcePerBlock();
          for (int row = 0; row < nb; ++row)
            for (int column = 0; column < nb; ++column) {
              o.localStatic.push_back(field.staticAt(row, column) / normal);
              o.localKinetic.push_back(field.kineticAt(row, column) / normal);
            }
        }
        for (auto& s : result.snapshots) {
          o.snapshotTime.push_back(s.time);
          o.snapshots.push_back(std::move(s.sigmaXOverP));
        }
        o.wallSeconds = wall;
        o.rank = rank;
        GF_CALL(PetscLogEventBegin(events.write, 0, 0, 0, 0));
        file.writeTask(o);
        GF_CALL(PetscLogEventEnd(events.write, 0, 0, 0, 0));
        ++finishedHere;
        taskSecondsHere += wall;
        const long all = counter.finishOne();
        if (monitor) {
          const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const long left = static_cast<long>(tasks.size()) - all;
          const double eta = all > 0 ? elapsed * left / all : NAN;
          std::printf("[%ld/%zu] point %d (%s) realisation %d: mu_s = %.6f, mu_k = %.6f%s  task %.2f s on rank %d;"
                      " elapsed %s, left ~%s\n",
                      all + alreadyDone, static_cast<size_t>(P) * R, task.point,
                      pointLabel(sweep, task.point).c_str(), task.realisation, o.muStatic, o.muKinetic,
                      o.peakConfirmed ? "" : " (peak unconfirmed)", wall, rank, hms(elapsed).c_str(),
                      left > 0 ? hms(eta).c_str() : "0:00:00");
          std::fflush(stdout);
        }
        abortIfDue(all);
      } catch (const std::exception& e) {
        failure = "task (point " + std::to_string(task.point) + ", realisation " + std::to_string(task.realisation) +
                  ") failed on rank " + std::to_string(rank) + ": " + e.what();
        std::fprintf(stderr, "ERROR: %s\n", failure.c_str());
        break;  // the other ranks finish their tasks; everything finished stays in the file
      }
    }
  }
  int failed = failure.empty() ? 0 : 1, anyFailed = 0;
  GF_CALL_MPI(MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, comm));
  file.flush();
  GF_CALL_MPI(MPI_Barrier(comm));
  if (anyFailed) {
    file.close();
    throw std::runtime_error("ensemble: a task failed (see the message above); the finished tasks are in " +
                             plan.workPath + ", continue with -ensemble_resume");
  }

  // ---- Statistics: every rank reads the small P x R tables and computes the same numbers. ----
  GF_CALL(PetscLogEventBegin(events.statistics, 0, 0, 0, 0));
  std::vector<PointStatistics> stats;
  {
    auto flags = file.finishedTasks();
    std::vector<unsigned char> done(flags.begin(), flags.end());
    auto confirmed = file.readPeakConfirmed();
    stats = pointStatistics(R, sweep.reference, file.readRealisationReal("mu_s"), file.readRealisationReal("mu_k"),
                            confirmed, done, commonStreams);
    std::vector<std::pair<std::string, std::vector<double>>> real;
    std::vector<std::pair<std::string, std::vector<int>>> integer;
    auto column = [&](const char* name, auto get) {
      std::vector<double> v;
      for (const auto& s : stats) v.push_back(get(s));
      real.emplace_back(name, std::move(v));
    };
    column("mu_s_mean", [](const PointStatistics& s) { return s.muStatic.mean; });
    column("mu_s_std", [](const PointStatistics& s) { return s.muStatic.stdDev; });
    column("mu_s_stderr", [](const PointStatistics& s) { return s.muStatic.stdError; });
    column("mu_s_ci95_low", [](const PointStatistics& s) { return s.muStatic.ciLow; });
    column("mu_s_ci95_high", [](const PointStatistics& s) { return s.muStatic.ciHigh; });
    column("mu_s_relative", [](const PointStatistics& s) { return s.muStaticRelative.value; });
    column("mu_s_relative_error", [](const PointStatistics& s) { return s.muStaticRelative.error; });
    column("mu_k_mean", [](const PointStatistics& s) { return s.muKinetic.mean; });
    column("mu_k_std", [](const PointStatistics& s) { return s.muKinetic.stdDev; });
    column("mu_k_stderr", [](const PointStatistics& s) { return s.muKinetic.stdError; });
    column("mu_k_ci95_low", [](const PointStatistics& s) { return s.muKinetic.ciLow; });
    column("mu_k_ci95_high", [](const PointStatistics& s) { return s.muKinetic.ciHigh; });
    column("mu_k_relative", [](const PointStatistics& s) { return s.muKineticRelative.value; });
    column("mu_k_relative_error", [](const PointStatistics& s) { return s.muKineticRelative.error; });
    auto icolumn = [&](const char* name, auto get) {
      std::vector<int> v;
      for (const auto& s : stats) v.push_back(get(s));
      integer.emplace_back(name, std::move(v));
    };
    icolumn("finished", [](const PointStatistics& s) { return s.finished; });
    icolumn("mu_s_count", [](const PointStatistics& s) { return s.muStatic.count; });
    icolumn("mu_k_count", [](const PointStatistics& s) { return s.muKinetic.count; });
    icolumn("peaks_unconfirmed", [](const PointStatistics& s) { return s.peaksUnconfirmed; });
    file.writeStatistics(real, integer);
  }
  file.markComplete();
  file.close();
  GF_CALL(PetscLogEventEnd(events.statistics, 0, 0, 0, 0));
  if (plan.workPath != plan.finalPath) {
    int renamed = 0;
    if (rank == 0) renamed = std::rename(plan.workPath.c_str(), plan.finalPath.c_str()) == 0 ? 1 : 0;
    GF_CALL_MPI(MPI_Bcast(&renamed, 1, MPI_INT, 0, comm));
    if (!renamed)
      throw std::runtime_error("ensemble: could not rename " + plan.workPath + " to " + plan.finalPath + ": " +
                               std::strerror(errno));
  }

  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  long ranHere = finishedHere, ranAll = 0;
  double taskSecondsAll = 0.0;
  GF_CALL_MPI(MPI_Allreduce(&ranHere, &ranAll, 1, MPI_LONG, MPI_SUM, comm));
  GF_CALL_MPI(MPI_Allreduce(&taskSecondsHere, &taskSecondsAll, 1, MPI_DOUBLE, MPI_SUM, comm));
  printStatistics(comm, sweep, R, stats, request.measurement.kinetic, commonStreams);
  // busy: the share of rank-seconds spent inside tasks (the rest: start-up, file writes, waiting
  // for the last task, statistics).
  GF_CALL(PetscPrintf(comm,
                      "\n%ld task(s) run in %s on %d rank(s): %.4g tasks/s, mean task %.4g s, ranks busy %.1f %%; "
                      "results in %s\n",
                      ranAll, hms(elapsed).c_str(), size, elapsed > 0 ? ranAll / elapsed : 0.0,
                      ranAll > 0 ? taskSecondsAll / ranAll : 0.0,
                      elapsed > 0 ? 100.0 * taskSecondsAll / (size * elapsed) : 0.0, plan.finalPath.c_str()));
}

}  // namespace gradfric::ensemble
