// What a spring-block scene run prints (include/gradfric/ensemble/scene_report.hpp).
#include "gradfric/ensemble/scene_report.hpp"

#include "gradfric/core/study_judgement.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/physics/observables.hpp"
#include "gradfric/sbm/model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gradfric::ensemble {

// The spring-block campaign is the campaign component's: its names without the prefix, in this file.
using namespace campaign;

namespace {

// The effects of the most strongly graded point (the sweep line lists the others).
void printActiveEffects(MPI_Comm comm, const Scene& scene) {
  int shown = scene.points() > 0 ? 0 : -1;
  double largest = -1.0;
  for (int p = 0; p < scene.points(); ++p) {
    const SweepPoint& q = scene.sweep.points[p];
    if (q.graded() && std::fabs(q.delta) > largest) {
      largest = std::fabs(q.delta);
      shown = p;
    }
  }
  if (scene.points() > 1) GF_CALL(PetscPrintf(comm, "  (for the sweep point with the strongest grading)\n"));
  const sbm::Parameters parameters = shown >= 0 ? scene.pointParameters(shown) : scene.parameters;
  const Grading grading = shown >= 0 ? scene.pointGrading(shown) : scene.baseGrading;
  for (const auto& e : sbm::activeEffects(parameters, grading, scene.request))
    GF_CALL(PetscPrintf(comm, "  - %s\n", e.c_str()));
}

void printSweep(MPI_Comm comm, const Scene& scene) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  const int P = scene.points(), R = scene.realisations, T = scene.tasks();
  std::string axes;
  for (const auto& a : scene.sweep.axes) axes += (axes.empty() ? "" : " x ") + a;
  GF_CALL(PetscPrintf(comm, "  - sweep: %s (%d point%s) x %d realisation%s = %d task%s on %d rank%s, %s schedule\n",
                      axes.empty() ? "none" : axes.c_str(), P, P == 1 ? "" : "s", R, R == 1 ? "" : "s", T,
                      T == 1 ? "" : "s", size, size == 1 ? "" : "s", scene.schedule.c_str()));
  if (scene.target.active())
    GF_CALL(PetscPrintf(comm,
                        "  - precision target: 95 %% CI half-width <= %g (%s) at every point; batches from %d "
                        "realisation(s) per point, at most %d\n",
                        scene.target.halfWidth, toString(scene.target.kind).c_str(), scene.target.first,
                        scene.target.cap));
  bool dispersed = false;  // the surface is the only random input of a realisation
  for (int p = 0; p < P && !dispersed; ++p) dispersed = scene.pointParameters(p).surface.dispersed();
  if (!dispersed && (R > 1 || scene.target.active()))
    GF_CALL(PetscPrintf(comm,
                        "  - the surface is undispersed at every point (-surface_sigma_s and _k 0): a point's "
                        "realisations are the same run, its CI of zero width (-ensemble_realisations 1 gives the same means)\n"));
  if (scene.stiffestFactor > 1.0)
    GF_CALL(PetscPrintf(comm, "  - one time step for the whole sweep, from its stiffest band (E x %g)\n",
                        scene.stiffestFactor));
  GF_CALL(PetscPrintf(comm, "  - stored: mu_s, mu_k per realisation%s%s%s\n",
                      scene.history ? ", mu(t) histories" : "", scene.request.measurement.firstSlipMap ? ", first-slip maps" : "",
                      scene.request.snapshotTimes.empty() ? "" : ", sigma_x/p snapshots"));
}

// Each point's discretisation bar with its basis (docs/accuracy.md, "The discretisation bar"); the
// points that share one line are listed together.
void printDiscretisation(MPI_Comm comm, const Scene& scene, bool kinetic) {
  std::vector<std::pair<std::string, std::string>> lines;  // (bar and basis, its points)
  for (int p = 0; p < scene.points(); ++p) {
    const std::string line = "discretisation " + study::describeBar(scene.discretisation(p, kinetic));
    auto same = std::find_if(lines.begin(), lines.end(), [&](const auto& l) { return l.first == line; });
    if (same == lines.end()) same = lines.insert(lines.end(), {line, ""});
    same->second += (same->second.empty() ? "" : ", ") + std::to_string(p);
  }
  for (const auto& [line, points] : lines) {
    const bool every = lines.size() == 1 && scene.points() > 1, several = points.find(',') != std::string::npos;
    GF_CALL(PetscPrintf(comm, "  %s%s: %s\n", every ? "every point" : several ? "points " : "point ",
                        every ? "" : points.c_str(), line.c_str()));
  }
}

// The spring-block study bounds mu_s and mu_k (sbm_error_estimate.hpp); other observables have no bar.
bool hasBar(const Observable& o) { return o.name == "mu_s" || o.name == "mu_k"; }

// The table of observable o (statisticsObservables()[o]) over the sweep points.
void printTable(MPI_Comm comm, const Scene& scene, const std::vector<PointStatistics>& stats, std::size_t o) {
  const Observable observable = statisticsObservables()[o];
  const std::string title = observable.title + " " + observable.name;
  if (scene.target.active())  // the counts per point are in column R
    GF_CALL(PetscPrintf(comm, "\n%s, realisations per point set by the target (95%% CI: Student t):\n", title.c_str()));
  else
    GF_CALL(PetscPrintf(comm, "\n%s over %d realisation(s) per point (95%% CI: Student t):\n", title.c_str(),
                        scene.realisations));
  GF_CALL(PetscPrintf(comm, "  %-5s %-32s %4s %10s %10s %10s %23s %19s %11s\n", "point", "sweep", "R", "mean", "std",
                      "std err", "95% CI", "rel. var. [%]", "discr. [%]"));
  // A pure number with 6 decimals (5 in the interval); others (times) with significant digits.
  const bool pure = observable.unit == "1";
  for (size_t p = 0; p < stats.size(); ++p) {
    const Summary& s = stats[p].observables[o].summary;
    const RelativeVariation& v = stats[p].observables[o].relative;
    char ci[64], rel[64];
    std::snprintf(ci, sizeof ci, pure ? "[%.5f, %.5f]" : "[%.4g, %.4g]", s.ciLow, s.ciHigh);
    // A point compared with itself has no variation to show (its 0 +- 0 is by definition).
    if (scene.sweep.reference[p] == static_cast<int>(p))
      std::snprintf(rel, sizeof rel, "%s", "reference");
    else if (std::isfinite(v.value))
      std::snprintf(rel, sizeof rel, "%+7.3f +- %.3f", 100 * v.value, std::isfinite(v.halfWidth) ? 100 * v.halfWidth : 0.0);
    else
      std::snprintf(rel, sizeof rel, "%s", "(no reference)");
    char discretisation[32] = "n/m";  // not measured: the reason follows the table
    if (hasBar(observable)) {
      const study::StudyBar& bar = scene.discretisation(static_cast<int>(p), observable.name == "mu_k");
      if (bar.measured) std::snprintf(discretisation, sizeof discretisation, "+- %.2f", 100 * bar.verdict.relative());
    }
    GF_CALL(PetscPrintf(comm, pure ? "  %-5zu %-32s %4d %10.6f %10.6f %10.6f %23s %19s %11s%s\n"
                                   : "  %-5zu %-32s %4d %10.4g %10.4g %10.4g %23s %19s %11s%s\n",
                        p, pointLabel(scene.sweep, static_cast<int>(p)).c_str(), s.count, s.mean, s.stdDev,
                        s.stdError, ci, rel, discretisation,
                        o == 0 && stats[p].peaksUnconfirmed ? "  (unconfirmed peaks)" : ""));
  }
  if (hasBar(observable)) printDiscretisation(comm, scene, observable.name == "mu_k");
}

// Which points met -ensemble_target, and which stopped at the cap.
void printTargetOutcome(MPI_Comm comm, const Scene& scene, const std::vector<PointStatistics>& stats) {
  std::string missed;
  for (int p = 0; p < scene.points(); ++p) {
    const double h = achievedHalfWidth(scene.target, stats, scene.sweep.reference, p);
    if (!(h <= scene.target.halfWidth)) missed += " " + std::to_string(p) + " (" + formatReal(h) + ")";
  }
  if (missed.empty())
    GF_CALL(PetscPrintf(comm, "Target met: 95 %% CI half-width (%s) <= %g at every point\n",
                        toString(scene.target.kind).c_str(), scene.target.halfWidth));
  else
    GF_CALL(PetscPrintf(comm,
                        "gradfric: warning: target %g (%s) NOT met at point(s)%s: -ensemble_target_max = %d "
                        "reached\n",
                        scene.target.halfWidth, toString(scene.target.kind).c_str(), missed.c_str(),
                        scene.target.cap));
}

void printStatistics(MPI_Comm comm, const Scene& scene, const std::vector<PointStatistics>& stats) {
  const std::vector<Observable> rows = statisticsObservables();
  if (scene.points() == 1 && scene.realisations == 1) {
    const auto& s = stats[0];
    std::string values;
    for (std::size_t o = 0; o < rows.size(); ++o)
      values += (o ? ", " : "") + rows[o].name + " = " + formatObservable(rows[o], s.observables[o].summary.mean);
    GF_CALL(PetscPrintf(comm, "\nResult: %s%s\n", values.c_str(),
                        s.peaksUnconfirmed ? "  (peak NOT confirmed before t_max: mu_s is the maximum reached)" : ""));
    for (bool kinetic : {false, true})
      if (!kinetic || scene.request.measurement.kinetic)
        GF_CALL(PetscPrintf(comm, "  %s: %s\n", kinetic ? "mu_k" : "mu_s", ("discretisation " + study::describeBar(scene.discretisation(0, kinetic))).c_str()));
    return;
  }
  for (std::size_t o = 0; o < rows.size(); ++o)  // an observable of the kinetic window only when it was measured
    if (!rows[o].kinetic || scene.request.measurement.kinetic) printTable(comm, scene, stats, o);
  GF_CALL(PetscPrintf(comm,
                      "  rel. var. = (mu - mu_0)/mu_0 against the non-graded point of the same angle and dispersion,"
                      " +- the 95 %% half-width: %s\n"
                      "  discr. = the discretisation uncertainty of the mean (the study's lattice ladder, docs/verification.md), "
                      "n/m: not measured\n",
                      scene.commonStreams ? "the paired differences' standard error x t(0.975, pairs - 1) (common random "
                                            "numbers)"
                                          : "the error propagated from both standard errors x t(0.975, min(n, n_0) - 1)"));
  if (scene.target.active()) printTargetOutcome(comm, scene, stats);
}

}  // namespace

void printScene(MPI_Comm comm, const Scene& scene, const RunParameters& record) {
  record.print(comm, "gradfric spring-block scene: resolved parameters");
  GF_CALL(PetscPrintf(comm, "Active effects:\n"));
  printActiveEffects(comm, scene);
  printSweep(comm, scene);
}

void printDryRun(MPI_Comm comm, const Scene& scene) {
  if (scene.target.active())  // the count follows from the results: the first batch and the cap
    GF_CALL(PetscPrintf(comm,
                        "Dry run (-ensemble_dry_run): scene checked, %d task(s) in the first batch, at most %d, "
                        "nothing run or written\n",
                        scene.points() * scene.target.first, scene.tasks()));
  else
    GF_CALL(PetscPrintf(comm, "Dry run (-ensemble_dry_run): scene checked, %d task(s) planned, nothing run or written\n",
                        scene.tasks()));
  GF_CALL(PetscPrintf(comm, "Discretisation bars (docs/verification.md):\n%s",
                      study::pointBarLines(scene.bars[0], scene.bars[1]).c_str()));
}

void printResults(MPI_Comm comm, const Scene& scene, const std::vector<PointStatistics>& statistics,
                  const TaskTally& tally, const std::string& resultsPath) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  printStatistics(comm, scene, statistics);
  // busy: the share of rank-seconds spent inside tasks (the rest: start-up, file writes, waiting
  // for the last task, statistics).
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - tally.start).count();
  GF_CALL(PetscPrintf(comm,
                      "\n%ld task(s) run in %s on %d rank(s): %.4g tasks/s, mean task %.4g s, ranks busy %.1f %%; "
                      "results in %s\n",
                      tally.ran, hms(elapsed).c_str(), size, elapsed > 0 ? tally.ran / elapsed : 0.0,
                      tally.ran > 0 ? tally.taskSeconds / tally.ran : 0.0,
                      elapsed > 0 ? 100.0 * tally.taskSeconds / (size * elapsed) : 0.0, resultsPath.c_str()));
}

}  // namespace gradfric::ensemble
