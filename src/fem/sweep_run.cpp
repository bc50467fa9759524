// Running an FEM sweep over groups of ranks (include/gradfric/fem/sweep.hpp).
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/format.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/campaign_batches.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/campaign/interruption.hpp"
#include "gradfric/campaign/resume_check.hpp"
#include "gradfric/campaign/runner.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/campaign/unconfirmed_peaks.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/fem/sweep.hpp"
#include "gradfric/io/output_plan.hpp"
#include "gradfric/io/provenance.hpp"
#include "gradfric/physics/observables.hpp"

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <cstdlib>
#include <string>

namespace gradfric::fem {

namespace {

// One run of the sweep on the group's communicator; the leader writes it into the file.
io::TaskOutput runTask(const FemSweep& s, const campaign::Task& task, MPI_Comm group, int worldRank) {
  FemParameters q = s.taskParameters(task);
  q.measurement.firstSlipMap = false;  // a sweep's file has no place for the FEM's node map: not recorded
  PlateModel model(group, q, s.pointGrading(task.point));
  const double wall0 = MPI_Wtime();
  io::TaskOutput o = taskOutputOf(runPlateExperiment(model));
  o.point = task.point;
  o.realisation = task.realisation;
  o.wallSeconds = MPI_Wtime() - wall0;
  o.rank = worldRank;  // the group's first rank
  return o;
}

// -fem_sweep_abort_after (testing only): exits abruptly, as a killed job would.
void abortIfDue(const FemSweep& s, long ranHere, int rank) {
  if (s.options.abortAfter <= 0 || ranHere < s.options.abortAfter) return;
  std::printf("fem sweep: -fem_sweep_abort_after %ld reached: rank %d exits abruptly (test of resume)\n",
              s.options.abortAfter, rank);
  std::fflush(stdout);
  std::_Exit(86);
}

void printPlan(MPI_Comm comm, const FemSweep& s, long finished) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  std::string axes;
  for (const auto& a : s.sweep.axes) axes += (axes.empty() ? "" : ",") + a;
  const std::string count =
      s.target.active() ? "up to " + std::to_string(s.realisations) + " realisation(s) per point (-ensemble_target " +
                              formatReal(s.target.halfWidth) + ", " + campaign::toString(s.target.kind) + ")"
                        : std::to_string(s.realisations) + " realisation(s) per point";
  const std::string pending =
      s.target.active() ? "batches to run" : std::to_string(static_cast<long>(s.tasks()) - finished) + " to run";
  GF_CALL(PetscPrintf(comm,
                      "FEM sweep: %d point(s) (axes: %s), %s, %s, on %d group(s) of %d rank(s); "
                      "%d x %d x %d hexahedra per run\n",
                      s.points(), axes.empty() ? "none" : axes.c_str(), count.c_str(), pending.c_str(),
                      size / s.options.ranksPerRun, s.options.ranksPerRun, s.params.nx, s.params.ny, s.params.nz));
  if (s.commonStreams)
    GF_CALL(PetscPrintf(comm, "  realisation r: the random surface r of seed %llu at every point (paired variations)\n",
                        static_cast<unsigned long long>(s.params.surface.seed)));
}

void printTable(MPI_Comm comm, const FemSweep& s, const std::vector<campaign::PointStatistics>& stats) {
  // Per observable (physics/observables.hpp): its value and relative variation; mu_s with its bar.
  const std::vector<Observable> rows = statisticsObservables();
  const bool ensemble = s.realisations > 1;
  const int width = ensemble ? 19 : 10, relativeWidth = ensemble ? 15 : 14;  // "mean+-half" and "+x+-y"
  std::string header = "  point sweep                   ";
  for (std::size_t o = 0; o < rows.size(); ++o) {
    char piece[96];
    std::snprintf(piece, sizeof piece, "%s %*s%s %*s", o ? "  " : "", width, rows[o].name.c_str(),
                  rows[o].name == "mu_s" ? " error [%]" : "", relativeWidth, "rel. var. [%]");
    header += piece;
  }
  GF_CALL(PetscPrintf(comm, "FEM sweep results (%s; relative variation against the non-graded point;\n"
                            "discretisation error bar of mu_s, 'n/m' where no study measured it):\n%s\n",
                      ensemble ? "means over the realisations +- their 95 % Student t half-widths" : "one run per point",
                      header.c_str()));
  // The reference point itself and a point without one show words, not a 0 or a nan.
  auto relative = [&](int p, const campaign::RelativeVariation& v) {
    char text[48];
    if (s.sweep.reference[p] == p) return std::string("reference");
    if (!std::isfinite(v.value)) return std::string("(no reference)");
    if (ensemble && std::isfinite(v.halfWidth))
      std::snprintf(text, sizeof text, "%+.3f+-%.3f", 100 * v.value, 100 * v.halfWidth);
    else
      std::snprintf(text, sizeof text, "%+.3f", 100 * v.value);
    return std::string(text);
  };
  for (int p = 0; p < s.points(); ++p) {
    const auto& st = stats[p];
    std::string line;
    for (std::size_t o = 0; o < rows.size(); ++o) {
      char piece[128], bar[32] = "";
      if (rows[o].name == "mu_s") {
        std::snprintf(bar, sizeof bar, " %s", "      n/m");
        if (s.bars[0][p].measured) std::snprintf(bar, sizeof bar, " %9.2f", 100 * s.bars[0][p].verdict.relative());
      }
      const campaign::Summary& m = st.observables[o].summary;
      char mean[48];
      if (ensemble)
        std::snprintf(mean, sizeof mean, rows[o].unit == "1" ? "%.6f+-%.6f" : "%.4g+-%.2g", m.mean, m.ciHalfWidth());
      else
        std::snprintf(mean, sizeof mean, rows[o].unit == "1" ? "%.6f" : "%.4g", m.mean);
      std::snprintf(piece, sizeof piece, "%s %*s%s %*s", o ? "  " : "", width, mean, bar, relativeWidth,
                    relative(p, st.observables[o].relative).c_str());
      line += piece;
    }
    const std::string runs = ensemble ? "  (" + std::to_string(st.finished) + " runs)" : "";
    GF_CALL(PetscPrintf(comm, "  %-5d %-24s%s%s%s\n", p, campaign::pointLabel(s.sweep, p).c_str(), line.c_str(),
                        runs.c_str(), st.peaksUnconfirmed > 0 ? "  (peak not confirmed)" : ""));
  }
}

// The group leader's line for a finished run: mu_k with its window's spread, and whether it was steady.
void printRun(const FemSweep& s, const campaign::Task& task, const io::TaskOutput& o, int group) {
  const FrictionSummary& f = o.friction;
  const std::string window = !f.kineticComplete ? ""
                             : " (window spread " + formatReal(100 * f.kineticSpread) + " %" +
                                   (!f.kineticSteadyTested ? ")" : f.kineticSteady ? ", steady)" : ", NOT steady)");
  const std::string realisation = s.realisations > 1 ? " realisation " + std::to_string(task.realisation) : "";
  // The flutter flag (docs/flutter.md): where nodes slid at mu > 1, the onset depends on the mesh.
  const std::string flutter = o.nodesSlidAboveOne > 0 ? ", flutter: " + std::to_string(o.nodesSlidAboveOne) +
                                                            " nodes slid at mu > 1 before the peak"
                                                      : "";
  std::printf("[group %d] point %d (%s)%s: %s%s%s%s  run %.2f s, %lld steps\n", group, task.point,
              campaign::pointLabel(s.sweep, task.point).c_str(), realisation.c_str(), observablesText(f).c_str(),
              window.c_str(), f.peakConfirmed ? "" : " (peak not confirmed)", flutter.c_str(), o.wallSeconds,
              static_cast<long long>(o.steps));
  std::fflush(stdout);
}

}  // namespace

io::TaskOutput taskOutputOf(const FemRunResult& run) {
  io::TaskOutput o;
  o.friction = run.friction;
  o.endTime = run.time.empty() ? 0.0 : run.time.back();
  o.steps = run.steps;
  if (run.resolution.applies) {
    o.nodesSlidAboveOne = run.resolution.aboveOne.nodes;
    o.areaSlidAboveOne = run.resolution.aboveOne.areaFraction;
  }
  return o;
}

bool runLengthFixed(const FemParameters& q, const RunParameters& record) {
  const ResolvedOption* slideTime = record.find("-fem_slide_time");
  return !q.stopWhenKnown || (slideTime && slideTime->origin == OptionOrigin::User);
}

int runFemSweep(MPI_Comm comm, const FemSweep& s, const RunParameters& record) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  const io::OutputPlan plan = campaign::planCampaignFile(comm, s);             // before any work
  // The tasks are points in a sweep of one run per point, runs in an ensemble.
  const std::string unit = s.realisations > 1 ? "runs" : "points";
  io::ResultsFile file = campaign::openCampaignFile(comm, s, plan, unit);  // a file to continue is checked first
  record.print(comm, "gradfric-fem: resolved parameters (FEM sweep)");
  printPlan(comm, s, file.finishedCount());
  const double wall0 = MPI_Wtime();
  // Round robin over the groups in the fixed order of pendingTasks (the static schedule): the same
  // tasks run on the same groups whatever the timing, and no number in the file depends on which
  // group ran it.
  campaign::ModelAdapter model;
  model.ranksPerRun = s.options.ranksPerRun;
  model.schedule = campaign::Schedule::Static;
  model.unit = unit;
  model.run = [&](const campaign::Task& task, MPI_Comm group) { return runTask(s, task, group, rank); };
  long ranHere = 0;  // over the batches: -fem_sweep_abort_after counts this group's runs
  model.finished = [&](const campaign::Task& task, const io::TaskOutput& o, long, long, bool leader) {
    if (leader) printRun(s, task, o, rank / s.options.ranksPerRun);
    abortIfDue(s, ++ranHere, rank);
  };
  model.failure = [&](const campaign::Task& task, int group, int, const std::string& what) {
    return "FEM sweep point " + std::to_string(task.point) + " (" + campaign::pointLabel(s.sweep, task.point) + ")" +
           (s.realisations > 1 ? " realisation " + std::to_string(task.realisation) : std::string()) +
           " failed in group " + std::to_string(group) + ": " + what;
  };
  long ran = 0;
  {
    const campaign::InterruptionNotice notice(comm, file, plan.workPath(), unit.c_str(), "-resume");  // Ctrl-C, SIGTERM
    campaign::runCampaignBatches(comm, s, file, [&](const std::vector<campaign::Task>& tasks, long, long) {
      campaign::runPending(comm, file, tasks, model, plan.workPath());
      ran += static_cast<long>(tasks.size());
    });
  }
  const auto stats = campaign::writeStatistics(file, s.realisations, s.sweep.reference, s.commonStreams,
                                               s.target.active() ? &s.target : nullptr);
  writeErrorBars(file, s);
  campaign::finishResultsFile(comm, file, plan);  // complete: renamed into place
  printTable(comm, s, stats);
  GF_CALL(PetscPrintf(comm, "FEM sweep: %ld run(s) in %.2f s wall; results in %s\n", ran, MPI_Wtime() - wall0,
                      plan.path().c_str()));
  return campaign::reportUnconfirmedPeaks(
      comm, "gradfric-fem", stats,
      {runLengthFixed(s.params, record), "-fem_slide_time or -fem_stop_when_known false", "-fem_slide_time"});
}

void writeErrorBars(io::ResultsFile& file, const FemSweep& s) {
  std::vector<std::pair<std::string, std::vector<double>>> values;
  for (int k = 0; k < 2; ++k) {
    const auto columns = campaign::discretisationValues(k ? "mu_k" : "mu_s", s.bars[k]);
    values.insert(values.end(), columns.begin(), columns.end());
  }
  file.writeStatistics(values, {});
}

}  // namespace gradfric::fem
