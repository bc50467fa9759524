// An ensemble of spring-block realisations at a trial l_z and sigma
// (include/gradfric/calibration/spring_block_evaluation.hpp).
#include "gradfric/calibration/spring_block_evaluation.hpp"

#include "gradfric/campaign/realisation_pool.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/sbm/model.hpp"
#include "gradfric/sbm/parameter_options.hpp"

#include <cmath>

namespace gradfric::calibration {

namespace {

// The mean shear-modulus factor of the blocks (1 for a plate without E grading).
double meanModulusFactor(const SpringBlockScene& scene) {
  const int n = scene.base.blocksPerSide;
  const PropertySampler sampler(scene.grading, n, n);
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) sum += sampler.modulus((i + 0.5) / n, (j + 0.5) / n);
  return sum / (static_cast<double>(n) * n);
}

}  // namespace

double stickingSlope(const SpringBlockScene& scene, double layerThickness) {
  const Plate& plate = scene.base.plate;
  return meanModulusFactor(scene) * plate.shearModulus() * plate.velocity / (plate.pressure * layerThickness);
}

double layerThicknessForSlope(const SpringBlockScene& scene, double slope) {
  return stickingSlope(scene, 1.0) / slope;
}

Evaluation evaluateSpringBlocks(MPI_Comm comm, const SpringBlockScene& scene, double layerThickness,
                                std::optional<double> sigma, const std::vector<double>& grid) {
  const double wall0 = MPI_Wtime();
  sbm::Parameters p = scene.base;
  p.layerThickness = layerThickness;
  if (sigma) p.surface.sigmaStatic = p.surface.sigmaKinetic = *sigma;
  p.automaticTimeStep = p.timeStep = sbm::defaultTimeStep(p, scene.grading);  // the step follows l_z
  RunParameters scratch;  // the -friction_ windows scale with the loading time, hence with l_z
  const sbm::Request request = sbm::readRequest(comm, &scratch, p, calibrationMeasurement());

  // One record per realisation: peak, slope, confirmed, wall, then the curve on the grid.
  const std::size_t G = grid.size(), width = 4 + G;
  const int R = scene.realisations;
  campaign::PoolPlan plan;
  plan.tasks = R;
  plan.width = static_cast<int>(width);
  plan.schedule = campaign::Schedule::Static;
  plan.failure = [](long r, int rank, const std::string& what) {
    return "realisation " + std::to_string(r) + " failed on rank " + std::to_string(rank) + ": " + what;
  };
  const std::vector<double> slots = campaign::runRealisationPool(comm, plan, [&](long r) {
    const sbm::Result result = sbm::simulate(p, scene.grading, request, StreamKey{scene.seed, 0, std::uint32_t(r)});
    const FrictionSummary& f = result.friction;
    const LoadingFeatures features = loadingFeatures(f.time, f.mu, scene.window, f.muStatic, f.peakTime);
    std::vector<double> slot{f.muStatic, features.slope, f.peakConfirmed ? 1.0 : 0.0, result.wallSeconds};
    const std::vector<double> curve = interpolate(f.time, f.mu, grid);
    slot.insert(slot.end(), curve.begin(), curve.end());
    return slot;
  });

  Evaluation e;
  e.layerThickness = layerThickness;
  e.sigma = p.surface.sigmaStatic;
  e.sigmaKinetic = p.surface.sigmaKinetic;
  e.timeStep = p.timeStep;
  std::vector<double> peaks(R), slopes(R);
  e.meanCurve.assign(G, 0.0);
  for (int r = 0; r < R; ++r) {
    const double* slot = &slots[static_cast<std::size_t>(r) * width];
    peaks[r] = slot[0];
    slopes[r] = slot[1];
    if (slot[2] == 0.0) ++e.unconfirmed;
    e.taskSeconds += slot[3];
    for (std::size_t k = 0; k < G; ++k) e.meanCurve[k] += slot[4 + k] / R;  // NaN stays NaN
  }
  e.peak = campaign::summarise(peaks);
  e.slope = campaign::summarise(slopes);
  e.wallSeconds = MPI_Wtime() - wall0;
  return e;
}

}  // namespace gradfric::calibration
