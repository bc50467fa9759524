#pragma once
// One evaluation of a calibration: an ensemble of spring-block realisations at a trial l_z (and,
// when sigma is fitted, a trial sigma = sigma_s = sigma_k; else the scene's surface), over the ranks of a communicator, and what it measures: the mean
// static peak and loading slope with their 95 % confidence intervals, and the mean mu(t). Every
// evaluation draws realisation r from the stream (seed, 0, r) (common random numbers): the
// measured quantities then move smoothly with l_z and sigma, which the secant steps need, and the
// final scene run by gradfric with the same seed gives the same numbers.
#include "gradfric/calibration/loading_curve.hpp"
#include "gradfric/campaign/statistics.hpp"
#include "gradfric/physics/friction_options.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <mpi.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace gradfric::calibration {

struct SpringBlockScene {
  sbm::Parameters base;  // the -sbm_ options; l_z, sigma and the time step are set per evaluation
  Grading grading;
  int realisations = 16;
  std::uint64_t seed = 1;
  LoadingWindow window;
};

struct Evaluation {
  double layerThickness = 0.0;  // l_z [m]
  double sigma = 0.0;           // sigma_s of the surface evaluated
  double sigmaKinetic = 0.0;    // its sigma_k
  double timeStep = 0.0;        // dt [s] (the shipped default for this l_z)
  campaign::Summary peak;       // mu_s over the realisations
  campaign::Summary slope;      // each realisation's loading slope [1/s]
  std::vector<double> meanCurve;  // mean mu on the comparison grid; NaN where a realisation had ended
  int unconfirmed = 0;            // realisations whose peak was not confirmed
  double wallSeconds = 0.0;       // of the whole evaluation
  double taskSeconds = 0.0;       // summed over the realisations
};

// Collective: realisation r runs on rank r % size (campaign/realisation_pool.hpp, static); the
// records are gathered whole, so every number is the same on any number of ranks, and a failing
// realisation ends every rank with the same error.
// sigma: nullopt keeps the scene's surface.
Evaluation evaluateSpringBlocks(MPI_Comm comm, const SpringBlockScene& scene, double layerThickness,
                                std::optional<double> sigma, const std::vector<double>& grid);

// The loading slope of the SBM's uniform start, G_mean v / (p l_z) [1/s] (every block sticks and
// its slider spring K_s = G l^2/l_z is the only compliance), and l_z from a measured slope.
double stickingSlope(const SpringBlockScene& scene, double layerThickness);
// mu_s-only runs stop at the confirmed peak: all a calibration needs (-friction_observables may ask more).
inline MeasurementDefaults calibrationMeasurement() {
  MeasurementDefaults d;
  d.observables = {"mu_s"};
  return d;
}
double layerThicknessForSlope(const SpringBlockScene& scene, double slope);

}  // namespace gradfric::calibration
