#pragma once
// Waiting for the other ranks without spinning. Open MPI polls at full speed inside a blocking
// collective, so a rank that has run out of tasks, or waits while rank 0 changes the results file
// alone, burns a core that another rank or another job could use. waitForRanks enters a
// non-blocking barrier and sleeps between tests (at most about a millisecond), which costs a
// waiting rank almost no CPU and the run at most that millisecond of latency.
#include <mpi.h>

namespace gradfric {

// Collective: returns once every rank of comm has called it.
void waitForRanks(MPI_Comm comm);

}  // namespace gradfric
