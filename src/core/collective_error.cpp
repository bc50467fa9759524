#include "gradfric/core/collective_error.hpp"

#include "gradfric/core/broadcast.hpp"

#include <cstdio>
#include <cstdlib>

namespace gradfric {

void agreeOnError(MPI_Comm comm, const std::string& localError) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // The lowest rank with an error tells the others its message.
  int mine = localError.empty() ? size : rank, first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == size) return;
  std::string message = localError;
  broadcast(comm, message, first);
  throw CollectiveError(message);
}

void abortJob(MPI_Comm comm, const std::string& message) {
  std::fprintf(stderr, "gradfric: error: %s\n", message.c_str());
  std::fflush(stderr);
  std::fflush(stdout);
  MPI_Abort(comm, 1);
  std::_Exit(1);  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

}  // namespace gradfric
