#pragma once
// What every gradfric driver does around its body: settle the command line (--names, -version,
// the options files), initialise MPI and PETSc,
// turn exceptions into one clear message and an exit code, finalise.
//   exit 0: success; 2: bad input (InputError); 3: PETSc error; 1: anything else.
#include <mpi.h>

#include <functional>

namespace gradfric {

int runDriver(int argc, char** argv, const char* help, const std::function<void(MPI_Comm)>& body);

}  // namespace gradfric
