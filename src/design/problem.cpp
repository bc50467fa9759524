// Reading an inverse-design problem (include/gradfric/design/problem.hpp).
#include "gradfric/design/problem.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/design/tao_search.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradfric::design {

namespace {

std::vector<std::string> splitNames(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    names.push_back(name);
  }
  if (!text.empty() && text.back() == ',') names.push_back("");  // a trailing comma: an empty item
  return names;
}

// Every corner of the bounds box (2^d points; d is small).
std::vector<std::vector<double>> corners(const std::vector<FreeParameter>& free) {
  std::vector<std::vector<double>> all(1);
  for (const auto& f : free) {
    std::vector<std::vector<double>> next;
    for (const auto& c : all)
      for (double v : {f.lower, f.upper}) {
        next.push_back(c);
        next.back().push_back(v);
      }
    all = next;
  }
  return all;
}

// The largest modulus factor of a plate on a 64 x 64 probe: the stiffest corner sets the step.
double largestModulus(const Grading& g) {
  const PropertySampler sampler(g, 64, 64);
  double largest = 0.0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) largest = std::max(largest, sampler.modulus((i + 0.5) / 64, (j + 0.5) / 64));
  return largest;
}

void checkParameterNames(const OptionReader& o, const std::vector<std::string>& names, const Grading& grading) {
  const std::string option = o.fullName("parameters");
  if (names.empty() || (names.size() == 1 && names[0].empty()))
    throw InputError(option, "(not set)",
                     "one or more free parameters: grading_delta or a field parameter <property>_<name> (mu_delta, E_exponent, ...)");
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) {
      std::string text;
      for (std::size_t k = 0; k < names.size(); ++k) text += (k ? "," : "") + names[k];
      throw InputError(option, text, "comma-separated parameter names, none empty (item " + std::to_string(i + 1) + " is)");
    }
    if (std::count(names.begin(), names.end(), names[i]) > 1)
      throw InputError(option, names[i], "each parameter once");
    if (names[i] == "grading_delta") {
      if (grading.profile == GradingProfile::None)
        throw InputError(option, names[i], "grading_delta only with -grading_profile linear or triangular");
      continue;
    }
    try {
      withParameter(grading.fields, names[i], 0.5);
    } catch (const std::invalid_argument& e) {
      throw InputError(option, names[i],
                       std::string("grading_delta or a parameter of a field the scene sets (-field_*): ") + e.what());
    }
  }
}

void checkBounds(const OptionReader& o, std::vector<FreeParameter>* free, const std::vector<double>& lower,
                 const std::vector<double>& upper) {
  const std::size_t d = free->size();
  for (const auto& [name, list] : {std::pair{"lower", &lower}, std::pair{"upper", &upper}})
    if (list->size() != d)
      throw InputError(o.fullName(name), list->empty() ? "(not set)" : std::to_string(list->size()) + " value(s)",
                       "one bound per free parameter (" + std::to_string(d) + ")");
  for (std::size_t i = 0; i < d; ++i) {
    (*free)[i].lower = lower[i];
    (*free)[i].upper = upper[i];
    if (!(lower[i] < upper[i]))
      throw InputError(o.fullName("upper"), formatReal(upper[i]),
                       "above -design_lower = " + formatReal(lower[i]) + " for " + (*free)[i].name);
    if ((*free)[i].name == "grading_delta" && !(lower[i] > -1.0 && upper[i] < 1.0))
      throw InputError(o.fullName(lower[i] <= -1.0 ? "lower" : "upper"), formatReal(lower[i] <= -1.0 ? lower[i] : upper[i]),
                       "-1 < Delta < 1 for grading_delta");
  }
}

}  // namespace

const char* toString(TargetKind kind) { return kind == TargetKind::Variation ? "variation" : "absolute"; }

Grading Problem::gradingAt(const std::vector<double>& x) const {
  Grading g = grading;
  for (std::size_t i = 0; i < free.size(); ++i) {
    if (free[i].name == "grading_delta")
      g.delta = x[i];
    else
      g.fields = withParameter(g.fields, free[i].name, x[i]);
  }
  return g;
}

Grading Problem::referenceGrading() const { return Grading{}; }

std::string Problem::describe(const std::vector<double>& x) const {
  std::string text;
  for (std::size_t i = 0; i < free.size(); ++i)
    text += (i ? ", " : "") + free[i].name + " = " + formatReal(x[i]);
  return text;
}

std::optional<Problem> readProblem(MPI_Comm comm, RunParameters* record) {
  Problem s;
  s.grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  s.grading.fields = readPlateFields(comm, record, plate, s.grading);
  OptionReader o(comm, "design_", "Inverse design", record);
  const std::string names = o.text("parameters", "",
                                   "free parameters, comma-separated: grading_delta or <property>_<name> of a field "
                                   "(mu_delta, E_exponent, mu_period, mu_duty, ...)");
  const std::vector<double> lower = o.realList("lower", {}, "(the parameter's)", "lower bound of each free parameter");
  const std::vector<double> upper = o.realList("upper", {}, "(the parameter's)", "upper bound of each free parameter");
  const std::string kind = o.choice("target_type", "absolute", {"absolute", "variation"},
                                    "what -design_target is: the plate's mean mu_s, or its relative variation "
                                    "(mu_s - mu_s,0) / mu_s,0 against the non-graded plate (paired streams)");
  const double target = o.real("target", 0.0, "1", "the target mu_s (absolute) or relative variation (e.g. -0.1)");
  s.tolerance = o.real("tolerance", 0.002, "1",
                       "the design's 95 % CI half-width must be at most this, and contain the target");
  const std::optional<double> coarse = o.realIfSet("coarse", "1", "CI half-width of evaluations far from the target",
                                                   "4 x -design_tolerance");
  const PetscInt first = o.integer("min_realisations", 8, 2, 10000000, "1", "realisations of an evaluation's first batch");
  const PetscInt cap = o.integer("max_realisations", 200, 2, 10000000, "1", "at most this many realisations per evaluation");
  const PetscInt evaluations = o.integer("max_evaluations", 20, 1, 100000, "1", "at most this many parameter values tried");
  const PetscInt scan = o.integer("scan_points", 3, 0, 1000, "1",
                                  "interior points tried when the bounds do not bracket the target (one parameter)");
  const std::string method = o.choice("method", "auto", {"auto", "root", "tao"},
                                      "search: the stochastic root finder (one parameter) or PETSc TAO (-design_tao_type nm, pounders); "
                                      "auto: root for one parameter, tao for several");
  const PetscInt seed = o.integer("seed", 1, 0, PETSC_MAX_INT, "1",
                                  "seed: realisation r of every evaluation draws from stream (seed, 0, r), the "
                                  "verification from (seed, 1, r)");
  const std::string model = o.choice("model", "sbm", {"sbm", "fem"},
                                     "what each evaluation runs: sbm (a spring-block ensemble) or fem (one gradfric-fem run "
                                     "on the -fem_* mesh, an undispersed surface; the spring blocks then give the "
                                     "model-form interval)");
  const std::vector<double> coarseMesh =
      o.realList("coarse_mesh", {}, "1",
                 "fem: nx,ny,nz of a coarse mesh the root finder searches on first; the design is then confirmed and "
                 "refined on the -fem_* mesh (empty: search on the -fem_* mesh)");
  const PetscInt fine = o.integer("fine_evaluations", 4, 1, 1000, "1",
                                  "fem with -design_coarse_mesh: at most this many runs on the -fem_* mesh (secant steps "
                                  "from the coarse design)");
  const std::string reuse = o.text("reuse", "",
                                   "fem, verify_fem: FEM runs taken instead of run again, comma-separated: earlier design "
                                   "files of -design_model fem with the same scene and FEM options (the same bits), or "
                                   "study tables (study: the FEM study table the bars come from; its rows keep 6 "
                                   "decimals)");
  const std::string variants =
      o.text("variants", "",
             "sbm: spring-block variants to run at the design (a friction law, a calibration), comma-separated options "
             "files of -sbm_*, -friction_*, -surface_* options laid over the scene; their spread is the design's "
             "variant interval");
  s.verify = o.flag("verify", true, "a fresh verification ensemble with independent streams at the design (sbm)");
  const bool verifyFem = o.flag("verify_fem", false,
                                "also run the design's surface in the finite-element model (-fem_* options: mesh, "
                                "penalties; a reduced mesh such as -fem_nx 20 -fem_ny 20 -fem_nz 2 is allowed; a variation "
                                "target: its non-graded plate too): the design's model-form interval");
  s.monitor = o.flag("monitor", true, "print a line per evaluation");
  s.plot = o.flag("plot", false, "draw the search with scripts/plot_design.py when the design completes");
  OptionReader out(comm, "", "Results file", record);
  s.output = out.text("output", "gradfric_design.h5", "design file: every evaluation, the design, its verification (HDF5)");
  s.overwrite = out.flag("output_overwrite", false, "replace an existing design file");
  const std::vector<std::string> parameterNames = splitNames(names);
  // The step needs the stiffest plate of the family: read -sbm_* once the bounds are known.
  if (!helpRequested()) {
    checkParameterNames(o, parameterNames, s.grading);
    for (const auto& n : parameterNames) s.free.push_back({n});
    checkBounds(o, &s.free, lower, upper);
  }
  Grading stiffest = s.grading;
  if (!helpRequested()) {
    double largest = 0.0;
    for (const auto& c : corners(s.free)) {
      const Grading g = s.gradingAt(c);
      if (largestModulus(g) > largest) {
        largest = largestModulus(g);
        stiffest = g;
      }
    }
  }
  s.parameters = sbm::readParameters(comm, record, plate, stiffest);
  s.request = sbm::readRequest(comm, record, s.parameters);
  s.model = model;
  if (verifyFem || model == "fem" || helpRequested()) s.fem = readFemCheck(comm, plate);
  if (helpRequested()) return std::nullopt;
  if (!reuse.empty()) s.reuse = splitNames(reuse);
  if (model != "fem" && !verifyFem && !s.reuse.empty())
    throw InputError(o.fullName("reuse"), reuse,
                     "only with -design_model fem or -design_verify_fem (a spring-block evaluation is an ensemble of "
                     "seconds, run again)");
  if (!variants.empty()) {
    if (model == "fem")
      throw InputError(o.fullName("variants"), variants,
                       "only with -design_model sbm (the variants are the spring blocks'; with the FEM they give the "
                       "model-form check, on the FEM's surface)");
    s.variants = readVariants(comm, splitNames(variants), plate, stiffest);
  }
  if (model != "fem" && (o.wasSet("coarse_mesh") || o.wasSet("fine_evaluations")))
    throw InputError(o.fullName(o.wasSet("coarse_mesh") ? "coarse_mesh" : "fine_evaluations"), "(set)",
                     "only with -design_model fem");
  if (model == "fem") {
    if (verifyFem)
      throw InputError(o.fullName("verify_fem"), "true",
                       "false with -design_model fem (the design is the FEM's; the spring blocks give its model-form check)");
    if (o.wasSet("verify"))
      throw InputError(o.fullName("verify"), s.verify ? "true" : "false",
                       "not set with -design_model fem (a FEM run is deterministic: rerun, it gives the same number)");
    if (s.fem->parameters.surface.dispersed())
      throw InputError("-surface_sigma_s", formatReal(s.fem->parameters.surface.sigmaStatic),
                       "0 (and -surface_sigma_k 0) with -design_model fem: one deterministic run per evaluation");
    s.verify = false;
    if (!coarseMesh.empty()) {
      const bool integers = coarseMesh.size() == 3 && std::all_of(coarseMesh.begin(), coarseMesh.end(), [](double v) {
        return v >= 1 && v <= 100000 && v == std::floor(v);
      });
      if (!integers)
        throw InputError(o.fullName("coarse_mesh"), "(" + std::to_string(coarseMesh.size()) + " values)",
                         "three whole numbers nx,ny,nz from 1 to 100000");
      s.coarseFem = std::make_shared<FemCheck>(*s.fem);
      s.coarseFem->parameters.nx = static_cast<int>(coarseMesh[0]);
      s.coarseFem->parameters.ny = static_cast<int>(coarseMesh[1]);
      s.coarseFem->parameters.nz = static_cast<int>(coarseMesh[2]);
      s.fineEvaluations = static_cast<int>(fine);
    } else if (o.wasSet("fine_evaluations")) {
      throw InputError(o.fullName("fine_evaluations"), std::to_string(fine), "only with -design_coarse_mesh");
    }
    // The spring blocks' model-form check stands on the FEM's surface.
    s.parameters.surface = s.fem->parameters.surface;
  }
  // Every evaluation moves the grading continuously: no measured g can match them all.
  if (s.parameters.pressureResponse.perGrading)
    throw InputError("-pressure_response_select", "grading",
                     "same under gradfric-design (its free parameters change the grading continuously, so no g "
                     "measured under one grading matches every evaluation)");
  for (const auto& c : corners(s.free)) {  // the family on the lattice at every corner, before any work
    try {
      checkSpringBlockFields(s.gradingAt(c), plate, s.parameters.blocksPerSide);
    } catch (const InputError& e) {
      throw InputError(o.fullName("upper"), s.describe(c), std::string("bounds inside which the plate is valid: ") + e.what());
    }
  }
  if (s.fem) {
    std::vector<Grading> all;
    for (const auto& c : corners(s.free)) all.push_back(s.gradingAt(c));
    if (kind == "variation") all.push_back(s.referenceGrading());  // the FEM's own reference run
    checkFemCheck(*s.fem, all);
    if (s.coarseFem) checkFemCheck(*s.coarseFem, all);
  }
  readDesignTaoOptions();  // -design_tao_*: read by TaoSetFromOptions later, checked now
  if (s.fem)
    checkUnusedOptions(comm, {"design_", "plate_", "surface_", "friction_", "sbm_", "grading_", "field_", "output", "fem_"});
  else
    checkUnusedOptions(comm, {"design_", "plate_", "surface_", "friction_", "sbm_", "grading_", "field_", "output"});
  if (!o.wasSet("target"))
    throw InputError(o.fullName("target"), "(not set)", "a target mu_s (absolute) or relative variation (variation)");
  s.kind = kind == "variation" ? TargetKind::Variation : TargetKind::Absolute;
  s.target = target;
  if (s.kind == TargetKind::Absolute && !(target > 0.0 && target < 10.0))
    throw InputError(o.fullName("target"), formatReal(target), "0 < mu_s < 10 under -design_target_type absolute");
  if (s.kind == TargetKind::Variation && !(target > -1.0 && target < 1.0))
    throw InputError(o.fullName("target"), formatReal(target), "-1 < variation < 1 under -design_target_type variation");
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0))
    throw InputError(o.fullName("tolerance"), formatReal(s.tolerance), "0 < tolerance < 1");
  s.coarse = coarse ? *coarse : 4.0 * s.tolerance;
  if (!coarse) o.recordDerived("coarse", s.coarse, "1", "CI half-width of evaluations far from the target = 4 x -design_tolerance");
  if (!(s.coarse >= s.tolerance && s.coarse < 1.0))
    throw InputError(o.fullName("coarse"), formatReal(s.coarse), "-design_tolerance <= coarse < 1");
  if (cap < first)
    throw InputError(o.fullName("max_realisations"), std::to_string(cap),
                     "at least -design_min_realisations = " + std::to_string(first));
  s.method = method == "auto" ? (s.dimension() == 1 ? "root" : "tao") : method;
  if (s.method == "root" && s.dimension() != 1)
    throw InputError(o.fullName("method"), method, "root with exactly one free parameter (-design_parameters has " +
                                                       std::to_string(s.dimension()) + "); tao for several");
  if (s.coarseFem && s.method != "root")
    throw InputError(o.fullName("coarse_mesh"), "(set)", "one free parameter (the root finder; TAO searches on one mesh)");
  s.firstBatch = static_cast<int>(first);
  s.cap = static_cast<int>(cap);
  s.maxEvaluations = static_cast<int>(evaluations);
  s.scanPoints = static_cast<int>(scan);
  s.seed = static_cast<std::uint64_t>(seed);
  measureMuStaticOnly(&s.request);
  return s;
}

void measureMuStaticOnly(sbm::Request* request) {
  request->measurement.kinetic = false;
  request->measurement.firstSlipMap = false;
  request->measurement.historyInterval = request->maxTime;
  request->snapshotTimes.clear();
}

}  // namespace gradfric::design
