#pragma once
// Collective: every rank's values, concatenated in rank order on rank 0 (empty on the others).
// For per-node records a rank-0 computation needs whole (the FEM's process zone, the pressure
// response map).
#include <mpi.h>

#include <vector>

namespace gradfric {

std::vector<double> gatherOnRoot(MPI_Comm comm, const std::vector<double>& local);

}  // namespace gradfric
