#include "gradfric/core/driver.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace gradfric {

namespace {

// PETSc would abort with a traceback on a missing -options_file; say it plainly instead.
bool sceneFilesExist(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "-options_file") == 0 || std::strcmp(argv[i], "-options_file_yaml") == 0) {
      if (!std::ifstream(argv[i + 1]).good()) {
        std::fprintf(stderr, "gradfric: error: invalid option %s = %s: allowed a readable scene file (not found)\n",
                     argv[i], argv[i + 1]);
        return false;
      }
    }
  }
  return true;
}

}  // namespace

int runDriver(int argc, char** argv, const char* help, const std::function<void(MPI_Comm)>& body) {
  if (!sceneFilesExist(argc, argv)) return 2;
  if (PetscInitialize(&argc, &argv, nullptr, help)) return 3;
  // PETSc errors come back as codes; GF_CALL turns them into exceptions with PETSc's message.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm comm = PETSC_COMM_WORLD;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int status = 0;
  try {
    body(comm);
  } catch (const InputError& e) {
    // Options are read identically on every rank, so every rank throws: rank 0 reports.
    if (rank == 0) std::fprintf(stderr, "gradfric: error: %s\n", e.what());
    status = 2;
  } catch (const CollectiveError& e) {
    // Agreed by every rank (e.g. a failed write or rename on rank 0, broadcast): rank 0 reports.
    if (rank == 0) std::fprintf(stderr, "gradfric: error: %s\n", e.what());
    status = 1;
  } catch (const PetscCallError& e) {
    std::fprintf(stderr, "gradfric: [rank %d] %s\n", rank, e.what());
    std::fflush(stderr);
    MPI_Abort(comm, 3);  // other ranks may be waiting in a collective
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gradfric: [rank %d] error: %s\n", rank, e.what());
    std::fflush(stderr);
    MPI_Abort(comm, 1);
  }
  PetscFinalize();
  return status;
}

}  // namespace gradfric
