// Running an FEM sweep over groups of ranks (include/gradfric/fem/sweep.hpp).
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/format.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/campaign/interruption.hpp"
#include "gradfric/campaign/resume_check.hpp"
#include "gradfric/campaign/runner.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
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

io::OutputPlan planSweepFile(MPI_Comm comm, const FemSweep& s) {
  io::OutputRequest request;
  request.option = "-output";
  request.path = s.output;
  request.temporarySuffix = ".partial";
  request.overwrite = s.params.overwrite;
  request.overwriteOption = "-output_overwrite";
  request.resume = s.options.resume;
  request.resumeOption = "-resume";
  return io::OutputPlan::decide(comm, request);
}

io::ResultsFile openSweepFile(MPI_Comm comm, const FemSweep& s, const io::OutputPlan& plan) {
  io::ResultsFile file = [&] {
    if (plan.start() == io::OutputStart::Fresh) {
      GF_CALL(PetscPrintf(comm, "Writing %s (renamed to %s when the sweep completes)\n", plan.workPath().c_str(),
                          plan.path().c_str()));
      return io::ResultsFile::create(comm, plan.workPath(), s.layout, s.table, s.sceneAttributes);
    }
    campaign::checkResumable(
        comm, campaign::ResumeTarget{s.sceneAttributes, s.layout, "-resume", "-output_overwrite"},
        plan.workPath());
    GF_CALL(PetscPrintf(comm, "Resuming %s\n", plan.workPath().c_str()));
    return io::ResultsFile::open(comm, plan.workPath());
  }();
  try {
    file.setRun(s.runAttributes, io::collectProvenance(comm));
  } catch (const CollectiveError& e) {
    if (plan.start() == io::OutputStart::Fresh) {
      plan.discard(comm);  // a new file without a run: nothing to keep
      throw;
    }
    throw CollectiveError(std::string(e.what()) + "; its finished points are kept: continue with -resume "
                                                   "once there is room");
  }
  return file;
}

// One run of the sweep on the group's communicator; the leader writes it into the file.
io::TaskOutput runPoint(const FemSweep& s, int point, MPI_Comm group, int worldRank) {
  FemParameters q = s.pointParameters(point);
  q.measurement.firstSlipMap = false;  // a sweep's file has no place for the FEM's node map: not recorded
  PlateModel model(group, q, s.pointGrading(point));
  const double wall0 = MPI_Wtime();
  FemRunResult r = runPlateExperiment(model);
  io::TaskOutput o;
  o.point = point;
  o.realisation = 0;
  o.friction = std::move(r.friction);
  o.endTime = r.time.empty() ? 0.0 : r.time.back();
  o.steps = r.steps;
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

void printPlan(MPI_Comm comm, const FemSweep& s, long pending) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  std::string axes;
  for (const auto& a : s.sweep.axes) axes += (axes.empty() ? "" : ",") + a;
  GF_CALL(PetscPrintf(comm,
                      "FEM sweep: %d point(s) (axes: %s), %ld to run, on %d group(s) of %d rank(s); "
                      "%d x %d x %d hexahedra per run\n",
                      s.points(), axes.empty() ? "none" : axes.c_str(), pending, size / s.options.ranksPerRun,
                      s.options.ranksPerRun, s.params.nx, s.params.ny, s.params.nz));
}

void printTable(MPI_Comm comm, const FemSweep& s, const std::vector<campaign::PointStatistics>& stats) {
  // Per observable (physics/observables.hpp): its value and relative variation; mu_s with its bar.
  const std::vector<Observable> rows = statisticsObservables();
  std::string header = "  point sweep                   ";
  for (std::size_t o = 0; o < rows.size(); ++o) {
    char piece[96];
    std::snprintf(piece, sizeof piece, "%s %10s%s %14s", o ? "  " : "", rows[o].name.c_str(),
                  rows[o].name == "mu_s" ? " error [%]" : "", "rel. var. [%]");
    header += piece;
  }
  GF_CALL(PetscPrintf(comm, "FEM sweep results (one run per point; relative variation against the non-graded point;\n"
                            "discretisation error bar of mu_s, 'n/m' where no study measured it):\n%s\n",
                      header.c_str()));
  // The reference point itself and a point without one show words, not a 0 or a nan.
  auto relative = [&](int p, double value) {
    char text[32];
    if (s.sweep.reference[p] == p) return std::string("reference");
    if (!std::isfinite(value)) return std::string("(no reference)");
    std::snprintf(text, sizeof text, "%+.3f", 100 * value);
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
      const double value = st.observables[o].summary.mean;
      std::snprintf(piece, sizeof piece, rows[o].unit == "1" ? "%s %10.6f%s %14s" : "%s %10.4g%s %14s", o ? "  " : "",
                    value, bar, relative(p, st.observables[o].relative.value).c_str());
      line += piece;
    }
    GF_CALL(PetscPrintf(comm, "  %-5d %-24s%s%s\n", p, campaign::pointLabel(s.sweep, p).c_str(), line.c_str(),
                        st.peaksUnconfirmed > 0 ? "  (peak not confirmed)" : ""));
  }
}

// The group leader's line for a finished point: mu_k with its window's spread, and whether it was steady.
void printPoint(const FemSweep& s, int point, const io::TaskOutput& o, int group) {
  const FrictionSummary& f = o.friction;
  const std::string window = !f.kineticComplete ? ""
                             : " (window spread " + formatReal(100 * f.kineticSpread) + " %" +
                                   (!f.kineticSteadyTested ? ")" : f.kineticSteady ? ", steady)" : ", NOT steady)");
  std::printf("[group %d] point %d (%s): %s%s%s  run %.2f s, %lld steps\n", group, point,
              campaign::pointLabel(s.sweep, point).c_str(), observablesText(f).c_str(), window.c_str(),
              f.peakConfirmed ? "" : " (peak not confirmed)", o.wallSeconds, static_cast<long long>(o.steps));
  std::fflush(stdout);
}

}  // namespace

void runFemSweep(MPI_Comm comm, const FemSweep& s, const RunParameters& record) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  const io::OutputPlan plan = planSweepFile(comm, s);  // before any work
  io::ResultsFile file = openSweepFile(comm, s, plan);    // a file to resume is checked first
  record.print(comm, "gradfric-fem: resolved parameters (FEM sweep)");
  const auto flags = file.finishedTasks();
  const std::vector<campaign::Task> pending =
      campaign::pendingTasks(s.sweep, 1, std::vector<unsigned char>(flags.begin(), flags.end()));
  printPlan(comm, s, static_cast<long>(pending.size()));
  const double wall0 = MPI_Wtime();
  // Round robin over the groups in the fixed order of pendingTasks (the static schedule): the same
  // points run on the same groups whatever the timing, and no number in the file depends on which
  // group ran it.
  campaign::ModelAdapter model;
  model.ranksPerRun = s.options.ranksPerRun;
  model.schedule = campaign::Schedule::Static;
  model.unit = "points";
  model.run = [&](const campaign::Task& task, MPI_Comm group) { return runPoint(s, task.point, group, rank); };
  model.finished = [&](const campaign::Task& task, const io::TaskOutput& o, long ranHere, long, bool leader) {
    if (leader) printPoint(s, task.point, o, rank / s.options.ranksPerRun);
    abortIfDue(s, ranHere, rank);
  };
  model.failure = [&](const campaign::Task& task, int group, int, const std::string& what) {
    return "FEM sweep point " + std::to_string(task.point) + " (" + campaign::pointLabel(s.sweep, task.point) +
           ") failed in group " + std::to_string(group) + ": " + what;
  };
  {
    const campaign::InterruptionNotice notice(comm, file, plan.workPath(), "points", "-resume");  // Ctrl-C, SIGTERM
    campaign::runPending(comm, file, pending, model, plan.workPath());
  }
  const auto stats = campaign::writeStatistics(file, 1, s.sweep.reference, false);
  writeErrorBars(file, s);
  campaign::finishResultsFile(comm, file, plan);  // complete: renamed into place
  printTable(comm, s, stats);
  GF_CALL(PetscPrintf(comm, "FEM sweep: %zu run(s) in %.2f s wall; results in %s\n", pending.size(),
                      MPI_Wtime() - wall0, plan.path().c_str()));
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
