#include "gradfric/core/quiet_wait.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <algorithm>
#include <ctime>

namespace gradfric {

void waitForRanks(MPI_Comm comm) {
  int size = 1;
  GF_CALL_MPI(MPI_Comm_size(comm, &size));
  if (size == 1) return;
  MPI_Request request = MPI_REQUEST_NULL;
  GF_CALL_MPI(MPI_Ibarrier(comm, &request));
  // The first tests come quickly (the others are usually there already); a long wait (the tail of
  // the task loop) is then polled every millisecond.
  long pauseNs = 20000;
  for (int done = 0;;) {
    GF_CALL_MPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
    if (done) return;
    const timespec pause{0, pauseNs};
    nanosleep(&pause, nullptr);
    pauseNs = std::min(2 * pauseNs, 1000000L);
  }
}

}  // namespace gradfric
