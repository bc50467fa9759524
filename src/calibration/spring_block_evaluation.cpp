// An ensemble of spring-block realisations at a trial l_z and sigma
// (include/gradfric/calibration/spring_block_evaluation.hpp).
#include "gradfric/calibration/spring_block_evaluation.hpp"

#include "gradfric/core/petsc_call.hpp"
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

Evaluation evaluateSpringBlocks(MPI_Comm comm, const SpringBlockScene& scene, double layerThickness, double sigma,
                                const std::vector<double>& grid) {
  int rank = 0, size = 1;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  const double wall0 = MPI_Wtime();
  sbm::Parameters p = scene.base;
  p.layerThickness = layerThickness;
  p.sigmaStatic = p.sigmaKinetic = sigma;
  p.automaticTimeStep = p.timeStep = sbm::defaultTimeStep(p, scene.grading);  // the step follows l_z
  RunParameters scratch;  // the -friction_ windows scale with the loading time, hence with l_z
  const sbm::Request request = sbm::readRequest(comm, &scratch, p, calibrationMeasurement());

  // One slot per realisation: peak, slope, confirmed, wall, then the curve on the grid.
  const std::size_t G = grid.size(), width = 4 + G;
  const int R = scene.realisations;
  std::vector<double> slots(static_cast<std::size_t>(R) * width, 0.0);
  for (int r = rank; r < R; r += size) {
    const sbm::Result result = sbm::simulate(p, scene.grading, request, StreamKey{scene.seed, 0, std::uint32_t(r)});
    const FrictionSummary& f = result.friction;
    const LoadingFeatures features = loadingFeatures(f.time, f.mu, scene.window, f.muStatic, f.peakTime);
    double* slot = &slots[static_cast<std::size_t>(r) * width];
    slot[0] = f.muStatic;
    slot[1] = features.slope;
    slot[2] = f.peakConfirmed ? 1.0 : 0.0;
    slot[3] = result.wallSeconds;
    const std::vector<double> curve = interpolate(f.time, f.mu, grid);
    std::copy(curve.begin(), curve.end(), slot + 4);
  }
  // Every slot comes from one rank (the others add 0): exact, whatever the number of ranks.
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, slots.data(), static_cast<int>(slots.size()), MPI_DOUBLE, MPI_SUM, comm));

  Evaluation e;
  e.layerThickness = layerThickness;
  e.sigma = sigma;
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
