// Reading and checking an FEM sweep (include/gradfric/fem/sweep.hpp): the options, the points,
// and the results file's layout, before any work.
#include "gradfric/fem/sweep.hpp"

#include "gradfric/study/scene_key.hpp"

#include "gradfric/fem/mesh_sites.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/campaign/sweep_options.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/property_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace gradfric::fem {

namespace {

// Options that steer how a sweep runs but not its numbers: stored under /run, so a resumed or
// re-ranked sweep of the same scene writes the same /scene (and may change them).
const std::set<std::string> kRunControl = {"-output",
                                           "-output_overwrite",
                                           "-resume",
                                           "-fem_sweep_abort_after",
                                           "-fem_sweep_ranks_per_run",
                                           "-fem_verbose",
                                           "-checkpoint_interval",
                                           "-checkpoint_file",
                                           "-checkpoint_test_signal",
                                           "-ensemble_extend"};

// mu(t) samples one run records at most: one at the start of sliding, then one per history
// interval, at most one per step (an interval below the step samples every step), up to the
// longest sliding time; a margin for the last step.
int historyCapacity(const FemSweep& s) {
  const FemParameters& q = s.params;
  double finest = std::numeric_limits<double>::infinity();  // the smallest step of any point
  for (int p = 0; p < s.points(); ++p) finest = std::min(finest, chooseTimeStep(s.pointParameters(p), s.pointGrading(p)));
  const double samples = std::floor(q.slideTime / std::max(q.measurement.historyInterval, finest)) + 4.0;
  if (!(samples <= 5e7))
    throw InputError("-friction_history_interval", formatReal(q.measurement.historyInterval),
                     "an interval giving at most 5e7 mu(t) samples per run up to -fem_slide_time");
  return static_cast<int>(samples);
}

// The centres [m] of the bottom cells along one axis of the mesh (unequal on a graded mesh).
std::vector<double> cellCentres(const MeshAxis& axis, int cells, double length) {
  std::vector<double> out;
  for (int i = 0; i < cells; ++i) out.push_back(axis.unitCentre(i) * length);
  return out;
}

// A sweep's layout, or a single run's (format kFemRunFormatName: no reference point, so no
// relative variation). With property fields, the maps' rows (cell_y).
io::EnsembleLayout layoutOf(const FemSweep& s, const char* format, bool fieldMaps) {
  io::EnsembleLayout layout;
  layout.format = format;
  layout.points = s.points();
  layout.realisations = s.realisations;  // one run per point without a random surface
  layout.historyCapacity = historyCapacity(s);
  // /properties: one column per bottom cell column along x, and per row along y with field maps.
  layout.cellX = cellCentres(meshAxisX(s.params), s.params.nx, s.params.plate.length);
  if (fieldMaps) layout.cellY = cellCentres(meshAxisY(s.params), s.params.ny, s.params.plate.length);
  // The columns campaign::writeStatistics writes (those of the spring-block ensemble's file; a
  // single run's without the relative variation), and each point's discretisation bar as fields
  // (sweep_run.cpp writes their values).
  layout.statistics = campaign::statisticsColumns(layout.singleRun() ? campaign::StatisticsFile::FemRun
                                                                     : campaign::StatisticsFile::FemSweep);
  for (int k = 0; k < 2; ++k) {
    const auto columns = campaign::discretisationColumns(k ? "mu_k" : "mu_s", s.bars[k]);
    layout.statistics.insert(layout.statistics.end(), columns.begin(), columns.end());
  }
  if (s.target.active()) {  // what the target asked and what each point reached
    const auto target = campaign::targetColumns();
    layout.statistics.insert(layout.statistics.end(), target.begin(), target.end());
  }
  return layout;
}

io::SweepTable tableOf(const FemSweep& s) {
  io::SweepTable table = campaign::sweepColumns(s.sweep);  // the ensemble's /sweep columns
  table.sigma.clear();  // but no sigma: the FEM sweep's one surface is in /scene (-surface_sigma_*)
  table.sigmaKinetic.clear();
  for (const auto& q : s.sweep.points)
    if (q.fieldSwept) table.fieldValue.push_back(q.fieldValue);
  const Plate& plate = s.params.plate;
  const int nx = static_cast<int>(s.params.nx), ny = static_cast<int>(s.params.ny);
  const MeshAxis columns = meshAxisX(s.params), rows = meshAxisY(s.params);
  for (int p = 0; p < s.points(); ++p) {  // the properties the run samples (as its history file has them)
    const Grading g = s.pointGrading(p);
    const PropertySampler sampler = meshSampler(g, columns, rows);
    for (int i = 0; i < nx; ++i) {  // each bottom cell column's centre on the middle row
      const double centre = columns.unitCentre(i);
      table.modulus.push_back(plate.youngsModulus * sampler.modulus(centre, 0.5));
      table.muStatic.push_back(plate.muStatic * sampler.muStatic(centre, 0.5));
      table.muKinetic.push_back(plate.muKinetic * sampler.muKinetic(centre, 0.5));
    }
    if (!g.fields) continue;
    // With fields, which may vary along y: the centre of every bottom cell, [ny][nx] (rows along y),
    // as a single run's /fem/fields has them.
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double u = columns.unitCentre(i), v = rows.unitCentre(j);
        table.blockModulus.push_back(plate.youngsModulus * sampler.modulus(u, v));
        table.blockMuStatic.push_back(plate.muStatic * sampler.muStatic(u, v));
        table.blockMuKinetic.push_back(plate.muKinetic * sampler.muKinetic(u, v));
        table.blockPressure.push_back(plate.pressure * sampler.pressure(u, v));
      }
  }
  return table;
}

// The point the sweep lists vary: the base run's grading and angle.
campaign::SweepPoint basePoint(const FemParameters& params, const Grading& grading) {
  campaign::SweepPoint base;
  base.delta = grading.delta;
  base.property = toString(grading.property);
  base.profile = toString(grading.profile);
  base.theta = params.plate.slidingAngle;
  base.sigma = params.surface.sigmaStatic;  // the study's scene key names the run's surface
  base.sigmaKinetic = params.surface.sigmaKinetic;
  return base;
}

// Each point's bars (before the layout, which stores their text).
void findStudyBars(const RunParameters& record, FemSweep* s) {
  for (int p = 0; p < s->points(); ++p)
    for (int k = 0; k < 2; ++k)
      s->bars[k].push_back(femStudyBar(record, &s->sweep.points[p], s->pointParameters(p), k ? "mu_k" : "mu_s"));
}

// The options into /scene (they define the results) and /run (they steer this run only).
// The target's options are not stored while it is off, nor -ensemble_extend unless set, so that
// the files of runs without them stay as they were.
}  // namespace

study::StudyBar femStudyBar(const RunParameters& record, const campaign::SweepPoint* point, const FemParameters& q,
                            const std::string& observable) {
  const study::SceneKey key = study::sceneKey(record, {"-fem_nx", "-fem_ny", "-fem_nz"}, point);
  return study::studyBar("fem_study.tsv", observable, key, {q.nx, q.ny, q.nz});
}

SweepOptions readSweepOptions(MPI_Comm comm, RunParameters* record) {
  SweepOptions s;
  OptionReader ens(comm, "ensemble_", "FEM sweep: the ensemble's sweep lists and realisations", record);
  s.realisations = campaign::readRealisationOptions(ens, "realisation r: the surface r of -fem_seed, at every point");
  s.lists = campaign::readSweepLists(ens);
  s.extend = ens.flag("extend", false,
                      "extend the finished -output file: more realisations or appended sweep points (or a tighter "
                      "target); what it holds is kept, not run again");
  OptionReader sw(comm, "fem_sweep_", "FEM sweep over groups of ranks (docs/fem.md)", record);
  const PetscInt ranks = sw.integer("ranks_per_run", 1, 1, 1000000, "1",
                                    "ranks of each run's sub-communicator; must divide the number of ranks");
  const PetscInt abortAfter = sw.integer(
      "abort_after", 0, 0, PETSC_MAX_INT, "1",
      "testing only: every rank exits abruptly (no close) once its group finished this many runs (0: never)");
  OptionReader out(comm, "", "Results file", record);
  s.resume = out.flag("resume", false,
                      "continue an interrupted run: a sweep skips the points finished in <-output>.partial, a single "
                      "run continues from its checkpoint (-checkpoint_file)");
  if (helpRequested()) return s;
  sw.requireAtLeast("ranks_per_run", ranks, 1);
  sw.requireAtLeast("abort_after", abortAfter, 0);
  s.ranksPerRun = static_cast<int>(ranks);
  s.abortAfter = static_cast<long>(abortAfter);
  s.requested = campaign::anySwept(s.lists) || sw.wasSet("ranks_per_run") || sw.wasSet("abort_after") ||
                ens.wasSet("realisations") || ens.wasSet("target") || s.extend;
  return s;
}

FemParameters FemSweep::pointParameters(int p) const {
  FemParameters q = params;
  q.plate.slidingAngle = sweep.points[p].theta;
  q.output.clear();  // a run of the sweep writes no file of its own
  q.snapshotTimes.clear();
  q.verbose = false;  // one line per finished run instead of every run's progress
  return q;
}

FemParameters FemSweep::taskParameters(const campaign::Task& task) const {
  FemParameters q = pointParameters(task.point);
  q.surfaceRealisation = static_cast<std::uint32_t>(task.realisation);
  return q;
}

FemSweep buildFemSweep(MPI_Comm comm, const FemParameters& params, const Grading& grading,
                       const SweepOptions& options, bool compareSbm, const RunParameters& record) {
  FemSweep s;
  s.params = params;
  s.baseGrading = grading;
  s.options = options;
  s.realisations = options.realisations.realisations;
  s.target = options.realisations.target;
  // Realisation r is the surface r at every point: paired relative variations, as the spring
  // blocks' common streams. Without a surface every realisation would be the same run.
  s.commonStreams = params.surface.dispersed();
  if (!s.commonStreams && (s.realisations > 1 || s.target.active())) {
    const bool target = s.target.active();
    throw InputError(target ? "-ensemble_target" : "-ensemble_realisations",
                     target ? formatReal(s.target.halfWidth) : std::to_string(s.realisations),
                     std::string(target ? "0" : "1") +
                         " without a random surface (every realisation would be the same run: set -surface_sigma_s or "
                         "-surface_sigma_k)");
  }
  s.resume = options.resume;
  s.extend = options.extend;
  s.overwrite = params.overwrite;
  if (!options.lists.sigma.empty())
    throw InputError("-ensemble_sigma", "(a list)",
                     "no sigma sweep in the FEM: one surface per FEM sweep, -surface_sigma_s and -surface_sigma_k (sweep sigma with gradfric)");
  campaign::checkSweepLists(options.lists, grading);
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  if (options.ranksPerRun > size || size % options.ranksPerRun != 0)
    throw InputError("-fem_sweep_ranks_per_run", std::to_string(options.ranksPerRun),
                     "a divisor of the number of ranks " + std::to_string(size) + " (1 .. " + std::to_string(size) + ")");
  if (!params.snapshotTimes.empty())
    throw InputError("-fem_snapshot_times", "(a list)",
                     "none in a sweep (field snapshots belong to one run: run that point alone)");
  if (compareSbm)
    throw InputError("-fem_compare_sbm", "true",
                     "false in a sweep (pair the sweep with a gradfric ensemble in scripts/gradfric_plot.py)");
  s.output = params.output.empty() ? "gradfric_fem_sweep.h5" : params.output;

  // A field sweep: the scene's fields with each value, every one checked on the mesh before any work.
  campaign::SweepLists lists = options.lists;
  const auto valueFields = campaign::fieldsPerValue(&lists, grading.fields);
  for (const auto& fields : valueFields) {
    Grading g = grading;
    g.fields = fields;
    checkMeshFields(g, params);
  }

  s.sweep = campaign::buildSweep(lists, basePoint(params, grading));
  for (const auto& q : s.sweep.points)  // each point's fields, in the ensemble's order
    if (q.fieldSwept) {
      const auto at = std::find(lists.fieldValues.begin(), lists.fieldValues.end(), q.fieldValue);
      s.pointFields.push_back(valueFields[at - lists.fieldValues.begin()]);
    }
  if (s.points() > 1000000) throw InputError("too many FEM sweep points: " + std::to_string(s.points()) + " > 1e6");
  campaign::checkRealisationPlan(s);
  for (int p = 0; p < s.points(); ++p)  // every task's step and run length, before any work
    for (int r = 0; r < s.realisations; ++r) {
      requireFemRunLength(s.taskParameters({p, r}), s.pointGrading(p), &record);
      if (!s.commonStreams) break;  // one surface: every realisation alike
    }
  findStudyBars(record, &s);
  s.table = tableOf(s);
  s.layout = layoutOf(s, io::kFemSweepFormatName, !s.table.blockModulus.empty());
  s.recordOptions(record, kRunControl);
  return s;
}

FemSweep oneRunCampaign(const FemParameters& params, const Grading& grading, const RunParameters& record) {
  FemSweep s;
  s.params = params;
  s.baseGrading = grading;
  s.sweep = campaign::buildSweep(campaign::SweepLists{}, basePoint(params, grading));  // no lists: one point
  s.output = params.output;
  findStudyBars(record, &s);
  s.table = tableOf(s);
  s.layout = layoutOf(s, io::kFemRunFormatName, !s.table.blockModulus.empty());
  s.recordOptions(record, kRunControl);
  return s;
}

}  // namespace gradfric::fem
