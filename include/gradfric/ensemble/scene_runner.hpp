#pragma once
// Runs a spring-block scene: every (sweep point, realisation) task over the ranks of comm,
// results gathered into one HDF5 file. Reads -ensemble_*, -output*, -sbm_*, -grading_* options,
// validates all of them before any work (throws InputError), and returns early, having printed
// the option lists, when -help was given.
#include "gradfric/core/options.hpp"

#include <mpi.h>

namespace gradfric::ensemble {

void runSpringBlockScene(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric::ensemble
