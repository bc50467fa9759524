// gradfric-study: what accuracy costs in time. Runs ladders of settings from a scene and reports
// the error of the global mu_s and mu_k against the finest setting, with the wall time.
//
//   mpiexec -n 2 gradfric-study -options_file input/study_sbm.opts -output study.h5
//   python3 scripts/plot_accuracy.py study.h5 docs/     (work-precision plots)
#include "gradfric/core/driver.hpp"
#include "gradfric/study/sbm_study.hpp"

static const char help[] =
    "gradfric-study: error of mu_s and mu_k against wall time for ladders of time step, integrator,\n"
    "lattice size and number of realisations. -help lists all options.\n\n";

int main(int argc, char** argv) {
  return gradfric::runDriver(argc, argv, help, [](MPI_Comm comm) {
    gradfric::RunParameters record;
    gradfric::study::runSpringBlockStudy(comm, &record);
  });
}
