// Reading a spring-block scene: every option read and checked before any work, then the sweep,
// the results file's layout and the attributes it stores.
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/study/scene_key.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/realisation_options.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/campaign/sweep_options.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace gradfric::ensemble {

// The spring-block campaign is the campaign component's: its names without the prefix, in this file.
using namespace campaign;

namespace {

// Options that steer one run but not its results: kept out of /scene (stored under /run), so a
// resumed or re-ranked run of the same scene writes the same /scene.
const std::set<std::string> kRunControl = {"-output",          "-output_overwrite",    "-resume",
                                           "-ensemble_monitor", "-ensemble_schedule",   "-ensemble_abort_after",
                                           "-ensemble_dry_run", "-ensemble_extend"};

// The largest modulus factor a grading reaches: the stiffest band sets the stable time step.
double stiffestFactorOf(const Grading& g) {
  double largest = 1.0;
  if (!g.gradesModulus()) return largest;
  for (int b = 0; b < g.bands; ++b) largest = std::max(largest, g.bandFactor(b));
  return largest;
}

// Upper bound of the number of mu(t) samples one task records (sbm::simulate samples at t = 0
// and then every history interval, at most once per step, and stops by t_max or t_end).
int historyCapacity(const sbm::Parameters& p, const sbm::Request& q) {
  double duration = q.maxTime;
  if (q.endTime > 0) duration = std::min(duration, q.endTime);
  const double dt = p.timeStep;
  const double steps = std::ceil(duration / dt) + 2.0;
  double samples = steps;
  const double interval = q.measurement.historyInterval;
  if (interval > dt) samples = std::min(samples, std::floor(duration / interval) + 3.0);
  if (samples > 5e7) throw InputError("-friction_history_interval", formatReal(interval),
                                      "an interval giving at most 5e7 mu(t) samples per realisation up to t_max");
  return static_cast<int>(samples) + 2;
}

// -ensemble_* and -output*: read in the order -help lists them.
SweepLists readEnsembleOptions(MPI_Comm comm, RunParameters* record, Scene* s) {
  OptionReader ens(comm, "ensemble_", "Ensemble of spring-block realisations", record);
  const RealisationPlan plan = readRealisationOptions(ens, "a new random surface each");  // a count or a target
  s->realisations = plan.realisations;
  s->target = plan.target;
  const PetscInt seed = ens.integer("seed", 1, 0, PETSC_MAX_INT, "1", "scene seed: a task's random stream is (seed, point, realisation)");
  SweepLists lists = readSweepLists(ens);  // shared with the FEM sweep (the field sweep too)
  // The same surface at every point, measured: the CI of the default scene's variation at
  // Delta = 0.2 is 12 % narrower (0.126 % against 0.144 %, 64 realisations; correlation of the
  // points' mu_s 0.33), and realisations compare across points (docs/surface.md).
  s->commonStreams = ens.flag(
      "common_streams", true,
      "the same random surface at every sweep point: realisation r is the surface (seed, 0, r), and relative "
      "variations use paired errors (false: each point its own surface (seed, point, r), as files before the "
      "surface)");
  s->history = ens.flag("history", true, "store the mu(t) history of every realisation");
  s->frictionFields = ens.flag(
      "friction_fields", false,
      "store every realisation's local mu_s,i and mu_k,i (2 N_b^2 values a task; they follow from the seed anyway)");
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  int interactive = rank == 0 ? isatty(STDOUT_FILENO) : 0;
  GF_CALL_MPI(MPI_Bcast(&interactive, 1, MPI_INT, 0, comm));
  s->monitor =
      ens.flag("monitor", interactive != 0, "print a progress line per finished task (default: on for a terminal)");
  s->extend = ens.flag("extend", false,
                       "extend the finished -output file: more realisations or appended sweep points (or a tighter "
                       "target); what it holds is kept, not run again");
  s->schedule = ens.choice("schedule", "dynamic", {"dynamic", "static"},
                           "task distribution: shared counter (one-sided MPI) or round robin");
  s->dryRun = ens.flag("dry_run", false, "check the scene and print the plan, run nothing, write nothing");
  const PetscInt abortAfter = ens.integer(
      "abort_after", 0, 0, PETSC_MAX_INT, "1",
      "testing only: every rank exits abruptly (no close, no finalize) once this many tasks finished (0: never)");
  OptionReader out(comm, "", "Results file", record);
  s->output = out.text("output", "gradfric_sbm.h5", "results file (parallel HDF5; see docs/ensemble.md)");
  s->overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  s->resume = out.flag("resume", false, "continue an interrupted run of the same scene (skips finished tasks)");
  if (helpRequested()) return lists;
  ens.requireAtLeast("seed", seed, 0);
  ens.requireAtLeast("abort_after", abortAfter, 0);
  s->seed = static_cast<std::uint64_t>(seed);
  s->abortAfter = static_cast<long>(abortAfter);
  return lists;
}

// The stiffest point of the sweep sets the stable time step: one dt for the whole sweep.
Grading stiffestGrading(const Sweep& sweep, const Grading& base, double* factor) {
  Grading stiffest = base;
  *factor = stiffestFactorOf(base);
  for (const auto& point : sweep.points) {
    const Grading g = gradingOf(point, base.bands);
    if (stiffestFactorOf(g) > *factor) {
      *factor = stiffestFactorOf(g);
      stiffest = g;
    }
  }
  return stiffest;
}

io::EnsembleLayout layoutOf(const Scene& s) {
  io::EnsembleLayout layout;
  layout.points = s.points();
  layout.realisations = s.realisations;
  layout.historyCapacity = s.history ? historyCapacity(s.parameters, s.request) : 0;
  layout.mapSide = s.parameters.blocksPerSide;
  layout.firstSlipMap = s.request.measurement.firstSlipMap;
  layout.frictionFields = s.frictionFields;
  layout.snapshotTimes = s.request.snapshotTimes;
  layout.statistics = statisticsColumns();
  // Each point's discretisation bar, as fields (campaign/statistics_columns.hpp).
  for (int k = 0; k < 2; ++k) {
    const auto columns = discretisationColumns(k ? "mu_k" : "mu_s", s.bars[k]);
    layout.statistics.insert(layout.statistics.end(), columns.begin(), columns.end());
  }
  if (s.target.active()) {  // what the target asked and what each point reached
    const auto target = targetColumns();
    layout.statistics.insert(layout.statistics.end(), target.begin(), target.end());
  }
  const double cells = static_cast<double>(layout.mapSide) * layout.mapSide;
  const double bytes = static_cast<double>(s.tasks()) *
                       (4.0 * layout.historyCapacity +  // time, mu, force_x, force_y
                        (layout.firstSlipMap ? cells : 0.0) + (layout.frictionFields ? 2.0 * cells : 0.0) +
                        layout.snapshotTimes.size() * (1.0 + cells)) *
                       8.0;
  if (bytes > 64e9)
    throw InputError("results file would need " + formatReal(bytes / 1e9) +
                     " GB: store fewer observables (-friction_observables, -sbm_snapshot_times), a coarser "
                     "-friction_history_interval or -ensemble_history false" +
                     std::string(s.target.active() ? " (the file is laid out for -ensemble_target_max realisations)"
                                                   : ""));
  return layout;
}

io::SweepTable tableOf(const Scene& s) {
  io::SweepTable table = sweepColumns(s.sweep);  // shared with the FEM sweep
  for (const auto& q : s.sweep.points)
    if (q.fieldSwept) table.fieldValue.push_back(q.fieldValue);
  for (int p = 0; p < s.points(); ++p) {  // the property fields each point uses (results file /properties)
    const Grading g = s.pointGrading(p);
    const sbm::ColumnProperties c = sbm::columnProperties(s.parameters, g);
    table.modulus.insert(table.modulus.end(), c.modulus.begin(), c.modulus.end());
    table.muStatic.insert(table.muStatic.end(), c.muStatic.begin(), c.muStatic.end());
    table.muKinetic.insert(table.muKinetic.end(), c.muKinetic.begin(), c.muKinetic.end());
    if (g.fields) {  // fields may vary along y: every block
      const sbm::BlockProperties b = sbm::blockProperties(s.parameters, g);
      table.blockModulus.insert(table.blockModulus.end(), b.modulus.begin(), b.modulus.end());
      table.blockMuStatic.insert(table.blockMuStatic.end(), b.muStatic.begin(), b.muStatic.end());
      table.blockMuKinetic.insert(table.blockMuKinetic.end(), b.muKinetic.begin(), b.muKinetic.end());
      table.blockPressure.insert(table.blockPressure.end(), b.pressure.begin(), b.pressure.end());
    }
  }
  return table;
}

}  // namespace

sbm::Parameters Scene::pointParameters(int p) const {
  sbm::Parameters q = parameters;
  q.plate.slidingAngle = sweep.points[p].theta;
  q.surface.sigmaStatic = sweep.points[p].sigma;
  q.surface.sigmaKinetic = sweep.points[p].sigmaKinetic;
  return q;
}

std::optional<Scene> readScene(MPI_Comm comm, RunParameters* record) {
  Scene s;
  s.baseGrading = readGrading(comm, record);
  const SweepLists lists = readEnsembleOptions(comm, record, &s);
  // The sweep without theta and sigma first: its stiffest point sets the time step of -sbm_*.
  SweepPoint base;
  base.delta = s.baseGrading.delta;
  base.property = toString(s.baseGrading.property);
  base.profile = toString(s.baseGrading.profile);
  Grading stiffest = stiffestGrading(buildSweep(lists, base), s.baseGrading, &s.stiffestFactor);
  const Plate plate = readPlate(comm, record);
  // The property fields are the same at every point (they replace the grading of their property).
  s.baseGrading.fields = stiffest.fields = readPlateFields(comm, record, plate, s.baseGrading);
  SweepLists allLists = lists;
  const std::vector<std::shared_ptr<const PlateFields>> valueFields = fieldsPerValue(&allLists, s.baseGrading.fields);
  // A swept E field: its stiffest value sets the time step (largest factor on a 64 x 64 probe).
  double stiffestField = 0.0;
  for (const auto& f : valueFields) {
    if (!f->modulus) break;
    Grading g = stiffest;
    g.fields = f;
    const PropertySampler sampler(g, 64, 64);
    double largest = 0.0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) largest = std::max(largest, sampler.modulus((i + 0.5) / 64, (j + 0.5) / 64));
    if (largest > stiffestField) {
      stiffestField = largest;
      stiffest.fields = f;
    }
  }
  s.parameters = sbm::readParameters(comm, record, plate, stiffest);
  s.request = sbm::readRequest(comm, record, s.parameters);
  if (helpRequested()) return std::nullopt;
  checkSweepLists(lists, s.baseGrading);
  refuseOverriddenBaseOptions(*record);
  for (std::size_t v = 0; v < valueFields.size(); ++v) {  // every swept field on the lattice, before any work
    Grading g = s.baseGrading;
    g.fields = valueFields[v];
    checkSpringBlockFields(g, plate, s.parameters.blocksPerSide);
  }
  checkUnusedOptions(comm, {"ensemble_", "plate_", "surface_", "friction_", "sbm_", "grading_", "field_", "pressure_", "output"});

  base.theta = s.parameters.plate.slidingAngle;
  base.sigma = s.parameters.surface.sigmaStatic;
  base.sigmaKinetic = s.parameters.surface.sigmaKinetic;
  s.sweep = buildSweep(allLists, base);
  for (const SweepPoint& q : s.sweep.points)  // each point's fields (the same for all without a field sweep)
    if (q.fieldSwept) {
      const auto at = std::find(allLists.fieldValues.begin(), allLists.fieldValues.end(), q.fieldValue);
      s.pointFields.push_back(valueFields[at - allLists.fieldValues.begin()]);
    }
  for (int p = 0; p < s.points(); ++p)  // -pressure_response_select grading: a g for every point
    (void)selectedFor(s.parameters.pressureResponse, s.pointGrading(p), s.pointParameters(p).plate.slidingAngle,
                      "sweep point " + std::to_string(p));
  checkRealisationPlan(s);
  for (int p = 0; p < s.points(); ++p) {  // the study's bar of each point (its scene and N_b)
    const study::SceneKey key = study::sceneKey(*record, {"-sbm_N"}, &s.sweep.points[p]);
    for (int k = 0; k < 2; ++k)
      s.bars[k].push_back(study::studyBar("sbm_study.tsv", k ? "mu_k" : "mu_s", key, {s.parameters.blocksPerSide}));
  }
  s.layout = layoutOf(s);
  s.table = tableOf(s);
  s.recordOptions(*record, kRunControl);
  return s;
}

}  // namespace gradfric::ensemble
