// gradfric: run a scene of the graded-friction toolkit.
//
//   mpiexec -n 2 gradfric -options_file input/default.opts [-sbm_N 60 ...] [-help]
//
// -model sbm (default) runs the spring-block scene: every (sweep point, realisation) task spread
// over the ranks, results in one HDF5 file (-output). -help lists every option with its default
// and unit. See README.md.
#include "gradfric/core/driver.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/ensemble/scene_runner.hpp"

static const char help[] =
    "gradfric: friction of elastic plates with laterally graded properties (spring-block model).\n"
    "Scenes are PETSc options files: gradfric -options_file input/default.opts; every option can be\n"
    "overridden on the command line. -help lists all options with defaults and units.\n\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    gradfric::RunParameters record;
    gradfric::ensemble::runSpringBlockScene(comm, &record);
  });
}
