#pragma once
// Sums over ranks that give the same bits on any number of ranks: each rank adds its terms into
// an ExactSum (core/exact_sum.hpp) and the digits are summed as integers, which no reduction
// order can change. One MPI_Allreduce for `count` sums.
#include "gradfric/core/exact_sum.hpp"

#include <mpi.h>

namespace gradfric {

// Collective: every sum becomes the total over the ranks of comm.
void allreduceExact(MPI_Comm comm, ExactSum* sums, int count);

// Collective: the total over the ranks of one exact sum, rounded once.
double sumOverRanks(MPI_Comm comm, const ExactSum& local);

}  // namespace gradfric
