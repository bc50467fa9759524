// The results file of a spring-block scene run (include/gradfric/ensemble/scene_file.hpp).
#include "gradfric/ensemble/scene_file.hpp"

#include "gradfric/io/provenance.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/campaign/log_events.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/physics/observables.hpp"

#include <limits>
#include <string>
#include <utility>

namespace gradfric::ensemble {

// The spring-block campaign is the campaign component's: its names without the prefix, in this file.
using namespace campaign;

io::OutputPlan planResultsFile(MPI_Comm comm, const Scene& scene) {
  io::OutputRequest request;
  request.option = "-output";
  request.path = scene.output;
  request.temporarySuffix = ".partial";
  request.overwrite = scene.overwrite;
  request.overwriteOption = "-output_overwrite";
  request.resume = scene.resume;
  request.resumeOption = "-resume";
  request.extend = scene.extend;
  request.extendOption = "-ensemble_extend";
  return io::OutputPlan::decide(comm, request);
}

io::ResultsFile openResultsFile(MPI_Comm comm, const Scene& scene, const io::OutputPlan& plan) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  io::ResultsFile file = [&] {
    if (plan.start() == io::OutputStart::ExtendFinished) {
      checkExtendable(comm, scene, plan.path());
      GF_CALL(PetscPrintf(comm, "Extending %s: writing %s with its tasks (renamed over it when the run completes)\n",
                          plan.path().c_str(), plan.workPath().c_str()));
      io::ResultsFile extended =
          io::ResultsFile::create(comm, plan.workPath(), scene.layout, scene.table, scene.sceneAttributes);
      extended.copyTasksFrom(plan.path());
      long kept = 0;
      for (auto flag : extended.finishedTasks()) kept += flag ? 1 : 0;
      GF_CALL(PetscPrintf(comm, "%ld task(s) kept from %s\n", kept, plan.path().c_str()));
      return extended;
    }
    if (plan.start() == io::OutputStart::Fresh) {
      GF_CALL(PetscPrintf(comm, "Writing %s (renamed to %s when the run completes)\n", plan.workPath().c_str(),
                          plan.path().c_str()));
      return io::ResultsFile::create(comm, plan.workPath(), scene.layout, scene.table, scene.sceneAttributes);
    }
    checkResumable(comm, scene, plan.workPath());
    GF_CALL(PetscPrintf(comm, "Resuming %s\n", plan.workPath().c_str()));
    io::ResultsFile resumed = io::ResultsFile::open(comm, plan.workPath());
    long finished = 0;
    for (auto flag : resumed.finishedTasks()) finished += flag ? 1 : 0;
    GF_CALL(PetscPrintf(comm, "%ld of %d tasks already finished; running the other %ld\n", finished, scene.tasks(),
                        scene.tasks() - finished));
    return resumed;
  }();
  try {
    file.setRun(scene.runAttributes, io::collectProvenance(comm));  // and version, command line, options files, date, ranks
  } catch (const CollectiveError& e) {
    const bool resumed = plan.start() == io::OutputStart::ContinueTemporary || plan.start() == io::OutputStart::ContinueFinished;
    if (!resumed) {
      plan.discard(comm);  // a new file without a task: nothing to keep
      throw;
    }
    throw CollectiveError(std::string(e.what()) + "; its finished tasks are kept: continue with -resume "
                                                   "once there is room");
  }
  return file;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, const Scene& scene) {
  auto stats = writeStatistics(file, scene.realisations, scene.sweep.reference, scene.commonStreams,
                               scene.target.active() ? &scene.target : nullptr);
  // Each point's discretisation bar as fields (their text attributes came with the layout).
  std::vector<std::pair<std::string, std::vector<double>>> bars;
  for (int k = 0; k < 2; ++k) {
    const auto values = discretisationValues(k ? "mu_k" : "mu_s", scene.bars[k]);
    bars.insert(bars.end(), values.begin(), values.end());
  }
  file.writeStatistics(bars, {});
  return stats;
}

}  // namespace gradfric::ensemble
