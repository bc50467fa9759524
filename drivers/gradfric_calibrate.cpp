// gradfric-calibrate: fits the spring-block model's l_z and sigma so that its ensemble matches a
// reference mu(t) (an FEM history or a measured curve) in loading slope and static peak, and
// writes a scene file with them (docs/calibration.md).
//
//   gradfric-fem -output fem.h5 -friction_observables mu_s
//   mpiexec -n 2 gradfric-calibrate -calibrate_reference fem.h5 -sbm_N 40 -output calibrated.opts
//   mpiexec -n 2 gradfric -options_file calibrated.opts -output calibrated.h5
#include "gradfric/calibration/calibration.hpp"
#include "gradfric/core/driver.hpp"

static const char help[] =
    "gradfric-calibrate: fits the spring-block l_z (loading slope) and sigma (static peak) to a reference mu(t)\n"
    "(-calibrate_reference: a gradfric-fem history, an HDF5 file, or a CSV t, mu) by secant steps on ensembles\n"
    "with common random numbers; prints the fitted values with 95 % uncertainties and residuals, and writes\n"
    "a scene file (-output) for gradfric. -help lists all options.\n\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    gradfric::RunParameters record;
    const auto calibration = gradfric::calibration::readCalibration(comm, &record);
    if (!calibration) return;  // -help
    record.print(comm, "gradfric-calibrate: resolved parameters");
    const auto result = gradfric::calibration::calibrate(comm, *calibration);
    gradfric::calibration::writeCalibration(comm, *calibration, result);
  });
}
