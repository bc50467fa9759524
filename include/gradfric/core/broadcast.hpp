#pragma once
// Broadcasts of values only one rank knows (a refusal message, a file's contents, a curve read
// on rank 0): the length first, then the data. Collective over comm.
#include <mpi.h>

#include <string>
#include <vector>

namespace gradfric {

void broadcast(MPI_Comm comm, std::string& text, int root = 0);
void broadcast(MPI_Comm comm, std::vector<double>& values, int root = 0);

}  // namespace gradfric
