#pragma once
// Collective gathers of every rank's values, concatenated in rank order.
// gatherOnRoot: on rank 0 (empty on the others), for per-node records a rank-0 computation needs
// whole (the FEM's process zone, the pressure response map). gatherOnAll: on every rank (the
// realisation pool's records and their task indices).
#include <mpi.h>

#include <vector>

namespace gradfric {

std::vector<double> gatherOnRoot(MPI_Comm comm, const std::vector<double>& local);
std::vector<double> gatherOnAll(MPI_Comm comm, const std::vector<double>& local);
std::vector<long> gatherOnAll(MPI_Comm comm, const std::vector<long>& local);

}  // namespace gradfric
