// gradfric: run a scene of the graded-friction toolkit.
//
//   mpiexec -n 2 gradfric -options_file input/default.opts [-sbm_N 60 ...] [-help]
//
// -model sbm (the default and only choice; the FEM is gradfric-fem) runs the spring-block scene: every (sweep point, realisation) task spread
// over the ranks, results in one HDF5 file (-output). -help lists every option with its default
// and unit. See README.md.
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/ensemble/scene_runner.hpp"

#include <petscsys.h>

#include <cstdlib>
#include <string>

static const char help[] =
    "gradfric: friction of elastic plates with laterally graded properties (spring-block model).\n"
    "Scenes are PETSc options files: gradfric -options_file input/default.opts; every option can be\n"
    "overridden on the command line. -help lists all options with defaults and units.\n\n";

namespace {

// -plot: draw the results file with scripts/gradfric_plot.py once the run is complete.
void plotResults(MPI_Comm comm, const gradfric::RunParameters& record, const std::string& folder) {
  const auto* output = record.find("-output");
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (!output || rank != 0) return;
  const std::string command = "/usr/bin/python3 '" GRADFRIC_SCRIPTS_DIR "/gradfric_plot.py' '" + output->value +
                              "'" + (folder.empty() ? "" : " --out '" + folder + "'");
  if (std::system(command.c_str()) != 0)
    std::fprintf(stderr, "gradfric: warning: plotting failed (%s); the results file is complete\n", command.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    gradfric::RunParameters record;
    gradfric::OptionReader model(comm, "", "Model", &record);
    model.choice("model", "sbm", {"sbm"}, "the spring-block model (the finite-element model is the gradfric-fem driver)");
    gradfric::OptionReader options(comm, "", "Plots", &record);
    const bool plot = options.flag("plot", false, "draw the results (mu(t), relative variation, maps) as PNG when the run completes");
    const std::string folder = options.text("plot_dir", "", "folder of the figures (default: beside the results file)");
    gradfric::ensemble::runSpringBlockScene(comm, &record);
    if (plot && !gradfric::helpRequested()) plotResults(comm, record, folder);
  });
}
