#pragma once
// What accuracy costs in time, for the spring-block model: the error of the global mu_s and mu_k
// and the wall time for ladders of settings (time step per integrator, lattice size, number of
// realisations), each against the finest setting of its ladder. Results go to a small HDF5 file
// (layout in docs/accuracy.md) and a table on stdout; scripts/plot_accuracy.py draws them.
#include "gradfric/core/options.hpp"

#include <mpi.h>

namespace gradfric::study {

// Reads -study_*, -sbm_*, -grading_*, -output*; tasks are spread over the ranks of comm by the
// realisation pool (campaign/realisation_pool.hpp; each measures its own wall time); rank 0 writes
// the file.
void runSpringBlockStudy(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric::study
