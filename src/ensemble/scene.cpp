// Reading a spring-block scene: every option read and checked before any work, then the sweep,
// the results file's layout and the attributes it stores.
#include "gradfric/ensemble/scene.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
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

namespace {

// Options that steer one run but not its results: kept out of /scene (stored under /run), so a
// resumed or re-ranked run of the same scene writes the same /scene.
const std::set<std::string> kRunControl = {"-output",          "-output_overwrite",    "-ensemble_resume",
                                           "-ensemble_monitor", "-ensemble_schedule",   "-ensemble_abort_after",
                                           "-ensemble_dry_run"};

// The largest modulus factor a grading reaches: the stiffest band sets the stable time step.
double stiffestFactorOf(const Grading& g) {
  double largest = 1.0;
  if (!g.gradesModulus()) return largest;
  for (int b = 0; b < g.bands; ++b) largest = std::max(largest, g.bandFactor(b));
  return largest;
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
  const double interval = q.measurement.historyInterval;
  if (interval > dt) samples = std::min(samples, std::floor(duration / interval) + 3.0);
  if (samples > 5e7) throw InputError("-friction_history_interval", formatReal(interval),
                                      "an interval giving at most 5e7 mu(t) samples per realisation up to t_max");
  return static_cast<int>(samples) + 2;
}

// -ensemble_* and -output*: read in the order -help lists them.
SweepLists readEnsembleOptions(MPI_Comm comm, RunParameters* record, Scene* s) {
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
  lists.fieldParameter = ens.text("field", "",
                                  "sweep of one scalar parameter of a property field, <property>_<parameter>: "
                                  "mu_delta, E_exponent, mu_period, p_position, ... (docs/fields.md)");
  lists.fieldValues = ens.realList("field_values", {}, "(the parameter's)", "the values of -ensemble_field, innermost loop");
  s->commonStreams = ens.flag(
      "common_streams", false,
      "common random numbers: realisation r of every sweep point draws from the stream (seed, 0, r); the "
      "relative variations then use paired errors");
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
  s->resume = ens.flag("resume", false, "continue an interrupted run of the same scene (skips finished tasks)");
  s->schedule = ens.choice("schedule", "dynamic", {"dynamic", "static"},
                           "task distribution: shared counter (one-sided MPI) or round robin");
  s->dryRun = ens.flag("dry_run", false, "check the scene and print the plan, run nothing, write nothing");
  const PetscInt abortAfter = ens.integer(
      "abort_after", 0, 0, PETSC_MAX_INT, "1",
      "testing only: every rank exits abruptly (no close, no finalize) once this many tasks finished (0: never)");
  OptionReader out(comm, "", "Results file", record);
  s->output = out.text("output", "gradfric_sbm.h5", "results file (parallel HDF5; see docs/ensemble.md)");
  s->overwrite = out.flag("output_overwrite", false, "replace an existing results file");
  for (double d : lists.delta)  // before the stable time step is computed from the sweep
    if (!(std::fabs(d) < 1.0)) throw InputError(ens.fullName("delta"), formatReal(d), "values with |Delta| < 1");
  if (helpRequested()) return lists;
  ens.requireAtLeast("realisations", realisations, 1);
  ens.requireAtLeast("seed", seed, 0);
  ens.requireAtLeast("abort_after", abortAfter, 0);
  s->realisations = static_cast<int>(realisations);
  s->seed = static_cast<std::uint64_t>(seed);
  s->abortAfter = static_cast<long>(abortAfter);
  return lists;
}

// One PlateFields per value of -ensemble_field_values (empty without a field sweep); the value
// that makes the field uniform, if any, becomes the sweep's reference.
std::vector<std::shared_ptr<const PlateFields>> fieldsPerValue(SweepLists* lists,
                                                               const std::shared_ptr<const PlateFields>& fields) {
  const bool named = !lists->fieldParameter.empty(), valued = !lists->fieldValues.empty();
  if (named != valued)
    throw InputError(named ? "-ensemble_field_values" : "-ensemble_field", "(not set)",
                     "both -ensemble_field and -ensemble_field_values, or neither");
  std::vector<std::shared_ptr<const PlateFields>> perValue;
  for (double v : lists->fieldValues) {
    try {
      perValue.push_back(withParameter(fields, lists->fieldParameter, v));
    } catch (const std::invalid_argument& e) {
      throw InputError("-ensemble_field", lists->fieldParameter, e.what());
    }
  }
  if (!perValue.empty()) {
    const PlateFields& f = *perValue.front();
    const std::string& name = lists->fieldParameter;
    const auto* swept = name.rfind("E_", 0) == 0 ? f.modulus.get() : name.rfind("p_", 0) == 0 ? f.pressure.get()
                        : name.rfind("mu_k_", 0) == 0 ? f.muKinetic.get() : f.muStatic.get();
    const bool amplitude = name.size() > 6 && name.compare(name.size() - 6, 6, "_delta") == 0 &&
                           swept->shape != FieldShape::Exponential && swept->shape != FieldShape::Bands &&
                           swept->shape != FieldShape::Map;
    const bool rate = name.size() > 9 && name.compare(name.size() - 9, 9, "_exponent") == 0 &&
                      swept->shape == FieldShape::Exponential;
    lists->fieldHasNeutral = amplitude || rate;
    lists->fieldNeutral = 0.0;
  }
  return perValue;
}

// The lists make sense together with the base grading.
void checkSweepLists(const SweepLists& lists, const Grading& base) {
  auto name = [](const char* n) { return std::string("-ensemble_") + n; };
  for (double t : lists.theta)
    if (!std::isfinite(t)) throw InputError(name("theta"), formatReal(t), "finite angles [degree]");
  for (double s : lists.sigma)
    if (!(s >= 0.0 && s <= 0.5)) throw InputError(name("sigma"), formatReal(s), "values with 0 <= sigma <= 0.5");
  const bool anyProfile = base.profile != GradingProfile::None ||
                          std::any_of(lists.profile.begin(), lists.profile.end(), [](auto& p) { return p != "none"; });
  const char* needProfile = "only with a grading profile: set -grading_profile linear or triangular (it is none)";
  if (!lists.delta.empty() && !anyProfile) throw InputError(name("delta"), "(a list)", needProfile);
  if (!lists.property.empty() && !anyProfile) throw InputError(name("property"), "(a list)", needProfile);
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
  layout.statisticsReal = {"mu_s_mean",      "mu_s_std",     "mu_s_stderr",         "mu_s_ci95_low",
                           "mu_s_ci95_high", "mu_s_relative", "mu_s_relative_error", "mu_k_mean",
                           "mu_k_std",       "mu_k_stderr",   "mu_k_ci95_low",       "mu_k_ci95_high",
                           "mu_k_relative",  "mu_k_relative_error"};
  layout.statisticsInteger = {"finished", "mu_s_count", "mu_k_count", "peaks_unconfirmed"};
  const double cells = static_cast<double>(layout.mapSide) * layout.mapSide;
  const double bytes = static_cast<double>(s.tasks()) *
                       (4.0 * layout.historyCapacity +  // time, mu, force_x, force_y
                        (layout.firstSlipMap ? cells : 0.0) + (layout.frictionFields ? 2.0 * cells : 0.0) +
                        layout.snapshotTimes.size() * (1.0 + cells)) *
                       8.0;
  if (bytes > 64e9)
    throw InputError("results file would need " + formatReal(bytes / 1e9) +
                     " GB: store fewer observables (-friction_observables, -sbm_snapshot_times), a coarser "
                     "-friction_history_interval or -ensemble_history false");
  return layout;
}

io::SweepTable tableOf(const Scene& s) {
  const Sweep& sweep = s.sweep;
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
  for (const auto& q : sweep.points)
    if (q.fieldSwept) table.fieldValue.push_back(q.fieldValue);
  for (int p = 0; p < s.points(); ++p) {  // the property fields each point uses (results file /properties)
    const Grading g = s.pointGrading(p);
    const sbm::Parameters& parameters = s.parameters;
    const sbm::ColumnProperties c = sbm::columnProperties(parameters, g);
    table.modulus.insert(table.modulus.end(), c.modulus.begin(), c.modulus.end());
    table.muStatic.insert(table.muStatic.end(), c.muStatic.begin(), c.muStatic.end());
    table.muKinetic.insert(table.muKinetic.end(), c.muKinetic.begin(), c.muKinetic.end());
    if (g.fields) {  // fields may vary along y: every block
      const sbm::BlockProperties b = sbm::blockProperties(parameters, g);
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
  q.sigmaStatic = sweep.points[p].sigma;
  q.sigmaKinetic = sweep.points[p].sigmaKinetic;
  return q;
}

Grading Scene::pointGrading(int p) const {
  Grading g = gradingOf(sweep.points[p], baseGrading.bands);
  g.fields = pointFields.empty() ? fields : pointFields[p];
  return g;
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
  s.fields = readPlateFields(comm, record, plate, s.baseGrading);
  s.baseGrading.fields = stiffest.fields = s.fields;
  SweepLists allLists = lists;
  const std::vector<std::shared_ptr<const PlateFields>> valueFields = fieldsPerValue(&allLists, s.fields);
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
  for (std::size_t v = 0; v < valueFields.size(); ++v) {  // every swept field on the lattice, before any work
    Grading g = s.baseGrading;
    g.fields = valueFields[v];
    checkSpringBlockFields(g, plate, s.parameters.blocksPerSide);
  }
  checkUnusedOptions(comm, {"ensemble_", "plate_", "friction_", "sbm_", "grading_", "field_", "output"});

  base.theta = s.parameters.plate.slidingAngle;
  base.sigma = s.parameters.sigmaStatic;
  base.sigmaKinetic = s.parameters.sigmaKinetic;
  s.sweep = buildSweep(allLists, base);
  for (const SweepPoint& q : s.sweep.points)  // each point's fields (the same for all without a field sweep)
    if (q.fieldSwept) {
      const auto at = std::find(allLists.fieldValues.begin(), allLists.fieldValues.end(), q.fieldValue);
      s.pointFields.push_back(valueFields[at - allLists.fieldValues.begin()]);
    }
  if (static_cast<double>(s.points()) * s.realisations > 2e9)
    throw InputError("too many tasks: sweep points x realisations > 2e9");
  s.layout = layoutOf(s);
  s.table = tableOf(s);
  for (const auto& o : record->all()) {
    io::Attribute a{stripDash(o.name), o.value, o.unit, originText(o.origin)};
    (kRunControl.count(o.name) ? s.runAttributes : s.sceneAttributes).push_back(a);
  }
  return s;
}

}  // namespace gradfric::ensemble
