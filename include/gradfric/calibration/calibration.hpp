#pragma once
// Calibration of the spring-block model against a reference mu(t) (gradfric-calibrate,
// docs/calibration.md). The slope of the SBM's sticking start is G v/(p l_z) (docs/model.md:
// slider springs K_s = G l^2/l_z), which gives the first l_z.
//  - fit lz (the default): l_z alone matches the reference's loading slope. sigma is the
//    surface's (-surface_*, the reference's with an FEM file); the peak's residual is what the
//    two models differ by on that surface, reported, not fitted away.
//  - fit lz_sigma: l_z and sigma (sigma_s = sigma_k) match the slope and the static peak, the
//    2 x 2 problem solved by secant (Broyden) steps.
// Ensembles use common random numbers; the fitted values carry the ensembles' confidence
// intervals through the final Jacobian. Steps: readCalibration (every option, the reference, the
// output files, before any work), calibrate, writeCalibration.
#include "gradfric/calibration/reference_curve.hpp"
#include "gradfric/calibration/spring_block_evaluation.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/io/output_plan.hpp"

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace gradfric::calibration {

enum class Fit { Layer, LayerAndSigma };

struct CalibrationSettings {
  ReferenceSource source;
  Fit fit = Fit::Layer;
  double layerGuess = 0.0;    // first l_z [m]; 0: from the reference's slope
  double sigmaGuess = 0.028;  // first sigma
  double sigmaStep = 0.01;    // the second sigma is sigmaGuess +- this (towards the reference's peak)
  double slopeTolerance = 0.002;  // |SBM slope / reference slope - 1| at most this
  double peakTolerance = 0.25;    // |SBM peak - reference peak| at most this fraction of the peak's CI half-width
  int maxEvaluations = 8;
  std::string output;       // the scene file
  std::string curveOutput;  // optional CSV: t, reference mu, mean SBM mu
};

struct Calibration {
  CalibrationSettings settings;
  SpringBlockScene scene;
  ReferenceCurve reference;
  LoadingFeatures target;      // the reference's slope and peak
  std::vector<double> grid;    // comparison times [s]: 0 .. 1.25 x the reference's peak time
  std::vector<ResolvedOption> sceneOptions;  // the user's SBM-scene options, copied into the scene file
  io::OutputPlan scenePlan;
  std::optional<io::OutputPlan> curvePlan;
};

// Collective: InputError (exit 2, on every rank) for anything that cannot run; nullopt after -help.
std::optional<Calibration> readCalibration(MPI_Comm comm, RunParameters* record);

struct CalibrationResult {
  std::vector<Evaluation> evaluations;
  int best = -1;            // the evaluation reported
  bool converged = false;   // the fitted residuals within their tolerances
  double layerError = 0.0;  // 95 % half-widths of the fitted l_z [m] and sigma
  double sigmaError = 0.0;
  double jacobian[2][2] = {{0, 0}, {0, 0}};  // d(slope ratio, peak)/d(l_z [m], sigma) at the end
  double wallSeconds = 0.0;
  long realisations = 0;  // spent over all evaluations
  const Evaluation& fitted() const { return evaluations[best]; }
};

// Collective: the evaluations, one line each. Fit::LayerAndSigma: CollectiveError if no sigma in
// [0, 0.5] can reach the reference's peak (the closest attainable value named).
CalibrationResult calibrate(MPI_Comm comm, const Calibration& calibration);

// Collective: the report, the scene file (and the curve file), each complete or not at all.
void writeCalibration(MPI_Comm comm, const Calibration& calibration, const CalibrationResult& result);

}  // namespace gradfric::calibration
