// gradfric: run a scene of the graded-friction toolkit.
//
//   mpiexec -n 2 gradfric -options_file input/default.opts [-sbm_N 60 ...] [-help]
//
// Runs the spring-block scene (the FEM is the driver gradfric-fem): every (sweep point,
// realisation) task spread over the ranks, results in one HDF5 file (-output). -help lists every
// option with its default and unit. See README.md and docs/ensemble.md.
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/campaign/interruption.hpp"
#include "gradfric/campaign/unconfirmed_peaks.hpp"
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/ensemble/scene_file.hpp"
#include "gradfric/ensemble/scene_report.hpp"
#include "gradfric/ensemble/task_runner.hpp"

#include <petscsys.h>

#include <cstdlib>
#include <optional>
#include <string>

static const char help[] =
    "gradfric: friction of elastic plates with laterally graded properties (spring-block model).\n"
    "Scenes are PETSc options files: gradfric -options_file input/default.opts; every option can be\n"
    "overridden on the command line. -help lists all options with defaults and units.\n\n";

namespace {

struct PlotRequest {
  bool plot = false;
  std::string folder;
};

PlotRequest readPlotOptions(MPI_Comm comm, gradfric::RunParameters* record) {
  gradfric::OptionReader options(comm, "", "Plots", record);
  PlotRequest r;
  r.plot = options.flag("plot", false, "draw the results (mu(t), relative variation, maps) as PNG when the run completes");
  r.folder = options.text("plot_dir", "", "folder of the figures (default: beside the results file)");
  return r;
}

// -plot: draw the results file with scripts/gradfric_plot.py once the run is complete.
void plotResults(MPI_Comm comm, const PlotRequest& request, const std::string& results) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (!request.plot || rank != 0) return;
  const std::string command = "/usr/bin/python3 '" GRADFRIC_SCRIPTS_DIR "/gradfric_plot.py' '" + results + "'" +
                              (request.folder.empty() ? "" : " --out '" + request.folder + "'");
  if (std::system(command.c_str()) != 0)
    std::fprintf(stderr, "gradfric: warning: plotting failed (%s); the results file is complete\n", command.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    using namespace gradfric;
    using namespace gradfric::ensemble;
    RunParameters record;
    refuseRetiredOption("-model", "gradfric runs the spring-block model only; the finite-element model is the driver gradfric-fem");
    const PlotRequest plot = readPlotOptions(comm, &record);
    const std::optional<Scene> scene = readScene(comm, &record);  // every option, checked
    if (!scene) return 0;                                         // -help
    printScene(comm, *scene, record);
    if (scene->dryRun) {
      printDryRun(comm, *scene);
      return 0;
    }
    const io::OutputPlan plan = campaign::planCampaignFile(comm, *scene);  // before any work
    std::optional<campaign::InterruptionNotice> notice(std::in_place, comm, plan.workPath(), scene->resume);  // Ctrl-C, SIGTERM
    io::ResultsFile file = campaign::openCampaignFile(comm, *scene, plan, "tasks");
    notice->watch(file, plan.workPath(), "tasks", "-resume");
    const TaskTally tally = runTasks(comm, *scene, file, plan.workPath());
    const std::vector<campaign::PointStatistics> statistics = writeStatistics(file, *scene);
    campaign::finishResultsFile(comm, file, plan);                // complete: renamed into place
    notice.reset();
    printResults(comm, *scene, statistics, tally, plan.path());
    plotResults(comm, plot, plan.path());
    // A realisation that gave up at -sbm_t_max has no static coefficient: exit 5, as the FEM's.
    const bool fixed = scene->request.endTime > 0;
    return campaign::reportUnconfirmedPeaks(comm, "gradfric", statistics, {fixed, "-sbm_t_end", "-sbm_t_max"});
  });
}
