#pragma once
// What every gradfric driver does around its body: settle the command line (--names, -version,
// the options files), initialise MPI and PETSc,
// turn exceptions into one clear message and an exit code, finalise.
//   exit 0: success; 2: bad input (InputError); 3: PETSc error; 1: anything else (an error all
//   ranks agreed on, CollectiveError, ends without MPI_Abort; any other one ends with MPI_Abort).
#include <mpi.h>

#include <functional>
#include <type_traits>

namespace gradfric {

// The body returns the driver's exit code once it has finished cleanly: 0, or an outcome of its
// own (gradfric-design's 4: target unreachable; gradfric-fem's 5: peak not confirmed at the run's
// default length). Errors take the codes above.
int runDriver(int argc, char** argv, const char* help, const std::function<int(MPI_Comm)>& body);

// A body without an outcome of its own: exit 0 when it finishes.
template <class Body, std::enable_if_t<std::is_void_v<std::invoke_result_t<Body&, MPI_Comm>>, int> = 0>
int runDriver(int argc, char** argv, const char* help, Body&& body) {
  return runDriver(argc, argv, help, std::function<int(MPI_Comm)>([&body](MPI_Comm comm) {
                     body(comm);
                     return 0;
                   }));
}

}  // namespace gradfric
