#include "gradfric/fem/scene_options.hpp"

#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/fem/parameter_options.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/fem/stable_step.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/grading_options.hpp"
#include "gradfric/physics/plate_options.hpp"

namespace gradfric::fem {

FemScene readFemScene(MPI_Comm comm, RunParameters* record) {
  FemScene scene;
  scene.grading = readGrading(comm, record);
  scene.plate = readPlate(comm, record);  // one plate for both models
  scene.params = readFemParameters(comm, record, scene.plate);
  scene.grading.fields = readPlateFields(comm, record, scene.plate, scene.grading);  // sampled at cells and nodes
  return scene;
}

void checkFemScene(MPI_Comm comm, const FemScene& scene, RunParameters* record,
                   const std::vector<std::string>& extraPrefixes) {
  checkMeshFields(scene.grading, scene.params);
  readPlateTSOptions(comm, scene.params);
  readPlateMeshOptions();  // -dm_view, -dm_plex_check_all: applied to the mesh once built  // the -fem_ts_ options: checked here, used by the run's TS
  std::vector<std::string> prefixes = {"plate_", "surface_", "friction_", "fem_", "grading_", "field_"};
  prefixes.insert(prefixes.end(), extraPrefixes.begin(), extraPrefixes.end());
  checkUnusedOptions(comm, prefixes);
  requireFemRunLength(scene.params, scene.grading, record);  // refuses a dt above the stable step, an endless run
}

std::optional<FemScene> readCheckedFemScene(MPI_Comm comm, RunParameters* record,
                                            const std::vector<std::string>& extraPrefixes) {
  FemScene scene = readFemScene(comm, record);
  if (helpRequested()) return std::nullopt;
  checkFemScene(comm, scene, record, extraPrefixes);
  return scene;
}

}  // namespace gradfric::fem
