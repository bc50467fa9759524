// The design's surface in the finite-element model (include/gradfric/design/fem_check.hpp).
#include "gradfric/design/fem_check.hpp"

#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/parameter_options.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/physics/field_options.hpp"

namespace gradfric::design {

std::shared_ptr<FemCheck> readFemCheck(MPI_Comm comm, const Plate& plate) {
  auto check = std::make_shared<FemCheck>();
  check->parameters = fem::readFemParameters(comm, &check->record, plate);
  // mu_s only, as the spring-block evaluations: the run stops at the confirmed peak.
  check->parameters.measurement.kinetic = false;
  check->parameters.measurement.firstSlipMap = false;
  // One line per evaluation is the design's progress; a run's own lines only when asked for.
  const ResolvedOption* verbose = check->record.find("-fem_verbose");
  if (!verbose || verbose->origin != OptionOrigin::User) check->parameters.verbose = false;
  fem::readPlateTSOptions(comm, check->parameters);
  fem::readPlateMeshOptions();
  return check;
}

void checkFemCheck(const FemCheck& check, const std::vector<Grading>& corners) {
  const fem::FemParameters& p = check.parameters;
  for (const Grading& g : corners) {
    fem::checkMeshFields(g, p);
    fem::requireFemRunLength(p, g, &check.record);
  }
}

FemRun runFemPlate(MPI_Comm comm, const FemCheck& check, const Grading& grading) {
  fem::PlateModel model(comm, check.parameters, grading);
  const double start = MPI_Wtime();
  const fem::FemRunResult r = fem::runPlateExperiment(model);
  FemRun run;
  run.muStatic = r.friction.muStatic;
  run.peakConfirmed = r.friction.peakConfirmed;
  run.wallSeconds = MPI_Wtime() - start;
  if (r.resolution.applies) run.flutter = {r.resolution.aboveOne.nodes, r.resolution.aboveOne.areaFraction};
  return run;
}

}  // namespace gradfric::design
