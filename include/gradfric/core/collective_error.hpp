#pragma once
// An error every rank of the communicator throws alike, because the ranks agreed on it (a flag
// reduced or broadcast before the next collective call): rank 0 alone reports it and the job ends
// with exit 1, without MPI_Abort. An error that can arise on one rank only must either be agreed
// this way or end the job at once (abortJob below), never unwind on one rank while others wait.
#include <mpi.h>

#include <stdexcept>
#include <string>

namespace gradfric {

class CollectiveError : public std::runtime_error {
public:
  explicit CollectiveError(const std::string& message) : std::runtime_error(message) {}
};

// Collective: `localError` is this rank's error (empty: none). If any rank has one, every rank
// throws the same CollectiveError carrying the message of the lowest such rank.
void agreeOnError(MPI_Comm comm, const std::string& localError);

// Collective: prints one line "gradfric: error: <message>" on this rank and ends every rank of comm
// with MPI_Abort (exit code 1). For failures other ranks cannot know about, e.g. inside a collective
// parallel-HDF5 call, where unwinding would call collective closes and hang.
[[noreturn]] void abortJob(MPI_Comm comm, const std::string& message);

}  // namespace gradfric
