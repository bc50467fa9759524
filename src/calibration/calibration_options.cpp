// Reading a calibration before any work (include/gradfric/calibration/calibration.hpp).
#include "gradfric/calibration/calibration.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <petscsys.h>

#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace gradfric::calibration {

namespace {

bool startsWith(const std::string& s, const char* head) { return s.rfind(head, 0) == 0; }

// The calibration owns l_z, the step that follows it, and sigma when it fits sigma: a value set
// for them is refused. Fitting l_z alone, the sigma guess and step have no effect: refused too.
void refuseOwnedOptions(Fit fit) {
  std::vector<std::pair<const char*, const char*>> owned = {
      {"-sbm_lz", "the calibration fits it (first guess: -calibrate_lz_guess)"},
      {"-sbm_dt", "the default step, which follows l_z (tune it with -sbm_dt_safety, -sbm_dt_slip)"}};
  if (fit == Fit::LayerAndSigma) {
    owned.push_back({"-surface_sigma_s", "-calibrate_fit lz_sigma fits it (first guess: -calibrate_sigma_guess)"});
    owned.push_back({"-surface_sigma_k", "-calibrate_fit lz_sigma fits it with sigma_s (one dispersion)"});
  } else {
    owned.push_back({"-calibrate_sigma_guess", "only with -calibrate_fit lz_sigma (l_z alone is fitted: sigma is the surface's)"});
    owned.push_back({"-calibrate_sigma_step", "only with -calibrate_fit lz_sigma (l_z alone is fitted: sigma is the surface's)"});
    owned.push_back({"-calibrate_peak_tolerance", "only with -calibrate_fit lz_sigma (fitting l_z alone, the peak is reported, not fitted)"});
  }
  for (const auto& o : owned) {
    PetscBool set = PETSC_FALSE;
    char value[256] = "";
    GF_CALL(PetscOptionsGetString(nullptr, nullptr, o.first, value, sizeof value, &set));
    if (set) throw InputError(o.first, value, std::string("not set in a calibration: ") + o.second);
  }
}

// With a gradfric-fem reference: the SBM scene describes the same plate, grading and fields, and,
// fitting l_z alone, the same surface (sigma is then the surface's, not a fitted constant).
void requireSamePlate(const ReferenceCurve& reference, const RunParameters& record, const std::string& path, Fit fit) {
  if (reference.scene.empty()) return;
  for (const auto& o : record.all()) {
    const std::string key = o.name.substr(1);
    const bool surface = fit == Fit::Layer && startsWith(key, "surface_");
    if (!(startsWith(key, "plate_") || startsWith(key, "grading_") || startsWith(key, "field_") || surface)) continue;
    if (key == "plate_nu" || key == "plate_H") continue;  // the lattice's nu is 1/3; H is the FEM's alone
    const auto it = reference.scene.find(key);
    if (it == reference.scene.end()) continue;
    char* end1 = nullptr;
    char* end2 = nullptr;
    const double a = std::strtod(o.value.c_str(), &end1), b = std::strtod(it->second.c_str(), &end2);
    const bool numbers = !o.value.empty() && !it->second.empty() && *end1 == '\0' && *end2 == '\0';
    const bool same = numbers ? std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b)) : o.value == it->second;
    if (!same)
      throw InputError(o.name, o.value,
                       "the reference's value " + it->second + " (" + path + "): calibrate the " +
                           (surface ? "surface" : "plate") + " the FEM ran");
  }
}

}  // namespace

std::optional<Calibration> readCalibration(MPI_Comm comm, RunParameters* record) {
  Calibration c;
  CalibrationSettings& s = c.settings;
  OptionReader o(comm, "calibrate_", "Calibration of the spring-block l_z (and sigma) (docs/calibration.md)", record);
  s.fit = o.choice("fit", "lz", {"lz", "lz_sigma"},
                   "lz: l_z alone matches the loading slope, sigma is the surface's (-surface_*, the FEM reference's); "
                   "lz_sigma: l_z and sigma (sigma_s = sigma_k) match the slope and the static peak") == "lz"
              ? Fit::Layer
              : Fit::LayerAndSigma;
  s.source.path = o.path("reference", "",
                         "the reference mu(t): a gradfric-fem results file (.h5), any HDF5 file with the datasets below, or a "
                         "CSV file (.csv) with columns t [s], mu");
  s.source.timeDataset = o.text("reference_time", s.source.timeDataset, "HDF5 reference: dataset of the times [s]");
  s.source.muDataset = o.text("reference_mu", s.source.muDataset, "HDF5 reference: dataset of mu");
  const std::vector<double> window = o.realList("window", {0.2, 0.6}, "1",
                                                "the loading slope is fitted where lo mu_s <= mu <= hi mu_s before the peak");
  const PetscInt realisations = o.integer("realisations", 16, 2, 100000, "1", "realisations per evaluation (an ensemble)");
  const PetscInt seed = o.integer("seed", 1, 0, PETSC_MAX_INT, "1", "realisation r draws from the stream (seed, 0, r) in every evaluation");
  s.layerGuess = o.real("lz_guess", 0.0, "m", "first l_z (0: G v / (p slope) from the reference's slope)");
  s.sigmaGuess = o.real("sigma_guess", s.sigmaGuess, "1", "lz_sigma: first sigma (sigma_s = sigma_k)");
  s.sigmaStep = o.real("sigma_step", s.sigmaStep, "1",
                       "lz_sigma: the second evaluation's sigma differs by this (towards the reference's peak)");
  s.slopeTolerance = o.real("slope_tolerance", s.slopeTolerance, "1", "converged when |slope / reference slope - 1| <= this");
  s.peakTolerance = o.real("peak_tolerance", s.peakTolerance, "1",
                           "lz_sigma: ... and |peak - reference peak| <= this x the 95 % CI half-width of the SBM's mean peak");
  const PetscInt evaluations = o.integer("max_evaluations", s.maxEvaluations, 2, 50, "1", "at most this many ensembles");
  s.curveOutput = o.text("curve", "", "optional CSV of the curves: t, reference mu, the calibrated ensemble's mean mu");
  OptionReader out(comm, "", "Scene file written", record);
  s.output = out.text("output", "calibrated.opts", "the scene file written: the SBM options with the fitted l_z and sigma");
  const bool overwrite = out.flag("output_overwrite", false, "replace existing -output / -calibrate_curve files");

  c.scene.grading = readGrading(comm, record);
  const Plate plate = readPlate(comm, record);
  c.scene.grading.fields = readPlateFields(comm, record, plate, c.scene.grading);
  if (!helpRequested()) refuseOwnedOptions(s.fit);
  c.scene.base = sbm::readParameters(comm, record, plate, c.scene.grading);
  // -help lists them; each evaluation re-derives them
  (void)sbm::readRequest(comm, record, c.scene.base, calibrationMeasurement());
  if (helpRequested()) return std::nullopt;
  // -pressure_response_select grading: the g of the calibrated grading, checked before any work.
  (void)selectedFor(c.scene.base.pressureResponse, c.scene.grading, c.scene.base.plate.slidingAngle, "the calibrated scene");

  if (s.source.path.empty())
    throw InputError(o.fullName("reference"), "(not set)",
                     "a gradfric-fem results file (.h5), an HDF5 file with -calibrate_reference_time/_mu, or a CSV file t, mu");
  if (window.size() != 2 || !(window[0] > 0 && window[0] < window[1] && window[1] < 1))
    throw InputError(o.fullName("window"), "(" + std::to_string(window.size()) + " values)", "lo,hi with 0 < lo < hi < 1");
  c.scene.window = LoadingWindow{window[0], window[1]};
  o.requireAtLeast("realisations", realisations, 2);
  o.requireAtLeast("seed", seed, 0);
  o.requireNonNegative("lz_guess", s.layerGuess, "m");
  o.requireRange("sigma_guess", s.sigmaGuess, 0.0, 0.5, "0 <= sigma_guess <= 0.5");
  o.requireRange("sigma_step", s.sigmaStep, 1e-4, 0.25, "1e-4 <= sigma_step <= 0.25");
  o.requireRange("slope_tolerance", s.slopeTolerance, 1e-6, 0.1, "1e-6 <= slope_tolerance <= 0.1");
  o.requireRange("peak_tolerance", s.peakTolerance, 1e-3, 1.0, "1e-3 <= peak_tolerance <= 1");
  o.requireAtLeast("max_evaluations", evaluations, 2);
  c.scene.realisations = static_cast<int>(realisations);
  c.scene.seed = static_cast<std::uint64_t>(seed);
  s.maxEvaluations = static_cast<int>(evaluations);
  checkUnusedOptions(comm, {"calibrate_", "plate_", "surface_", "friction_", "sbm_", "grading_", "field_"});

  // The reference and what it measures, before any work.
  s.source.option = o.fullName("reference");
  c.reference = readReferenceCurve(comm, s.source);
  c.target = loadingFeatures(c.reference.time, c.reference.mu, c.scene.window, c.reference.peak, c.reference.peakTime);
  if (!(c.target.peak > 0) || c.target.samples < 3 || !(c.target.slope > 0))
    throw InputError(s.source.option, s.source.path,
                     "a curve that rises through " + formatReal(window[0]) + "-" + formatReal(window[1]) +
                         " of its peak before it (" + std::to_string(c.target.samples) + " samples there, peak " +
                         formatReal(c.target.peak) + ")");
  requireSamePlate(c.reference, *record, s.source.path, s.fit);
  const double guess = s.layerGuess > 0 ? s.layerGuess : layerThicknessForSlope(c.scene, c.target.slope);
  if (!(guess > 1e-9 && guess < 1.0))
    throw InputError(o.fullName(s.layerGuess > 0 ? "lz_guess" : "reference"),
                     s.layerGuess > 0 ? formatReal(s.layerGuess) : s.source.path,
                     "a first l_z between 1e-9 and 1 m (from the slope: " + formatReal(guess) + " m)");
  s.layerGuess = guess;
  const int points = 400;
  const double end = std::min(1.25 * c.target.peakTime, c.reference.time.back());
  for (int k = 0; k <= points; ++k) c.grid.push_back(end * k / points);

  // The user's options of the SBM scene, for the scene file (the fitted ones are added to them).
  for (const auto& r : record->all()) {
    const std::string key = r.name;
    // (sigma_s and sigma_k are written after them, fitted or the surface's)
    if (r.origin != OptionOrigin::User || key == "-friction_observables" || key == "-surface_sigma_s" ||
        key == "-surface_sigma_k")
      continue;
    if (startsWith(key, "-plate_") || startsWith(key, "-grading_") || startsWith(key, "-field_") ||
        startsWith(key, "-sbm_") || startsWith(key, "-friction_") || startsWith(key, "-surface_"))
      c.sceneOptions.push_back(r);
  }
  // The files, planned before any work: complete or not at all.
  io::OutputRequest scene;
  scene.option = out.fullName("output");
  scene.path = s.output;
  scene.overwrite = overwrite;
  scene.overwriteOption = out.fullName("output_overwrite");
  c.scenePlan = io::OutputPlan::decide(comm, scene);
  if (!s.curveOutput.empty()) {
    io::OutputRequest curve = scene;
    curve.option = o.fullName("curve");
    curve.path = s.curveOutput;
    c.curvePlan = io::OutputPlan::decide(comm, curve);
  }
  return c;
}

}  // namespace gradfric::calibration
