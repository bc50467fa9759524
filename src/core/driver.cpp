#include "gradfric/core/driver.hpp"

#include "gradfric/core/command_line.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/version.hpp"

#include <petscsys.h>

#include <cstdio>
#include <string>
#include <vector>

namespace gradfric {

namespace {

// Every rank settles the same command line and reaches the same verdict; the lowest rank that
// found a problem prints it (one line in all), and every rank returns 2 together: no rank waits alone.
bool commandLineIsSound(MPI_Comm comm, const SettledCommandLine& settled) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int reporter = settled.problem.empty() ? size : rank;
  int firstReporter = size;
  MPI_Allreduce(&reporter, &firstReporter, 1, MPI_INT, MPI_MIN, comm);
  if (firstReporter == rank) {
    std::fprintf(stderr, "gradfric: error: %s\n", settled.problem.c_str());
    std::fflush(stderr);
  }
  return firstReporter == size;
}

// Runs the body with PETSc; returns the exit code.
int runWithPetsc(const std::vector<std::string>& arguments, const char* help,
                 const std::function<int(MPI_Comm)>& body) {
  // PETSc keeps argv for the whole run: the words live in `arguments` (runDriver's).
  std::vector<char*> words;
  for (const auto& a : arguments) words.push_back(const_cast<char*>(a.c_str()));
  words.push_back(nullptr);
  int argc = static_cast<int>(arguments.size());
  char** argv = words.data();
  if (PetscInitialize(&argc, &argv, nullptr, help)) return 3;
  // PETSc errors come back as codes; GF_CALL turns them into exceptions with PETSc's message.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm comm = PETSC_COMM_WORLD;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int status = 0;
  try {
    refuseRenamedRunControl();  // every driver speaks -output, -output_overwrite, -resume
    status = body(comm);
    if (helpRequested()) {
      printHelpSections(comm);
      if (!helpFilter().empty() && helpLinesPrinted() == 0)
        PetscPrintf(comm, "No option of this driver starts with -%s (-help alone lists them all)\n", helpFilter().c_str());
    }
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

}  // namespace

// MPI starts before PETSc so that the command line (--names, -version, the options files, stray
// words) is settled on every rank before PETSc reads it; PETSc then leaves MPI to us to finalise.
int runDriver(int argc, char** argv, const char* help, const std::function<int(MPI_Comm)>& body) {
  normaliseArguments(argc, argv);
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  int status = 0;
  if (versionRequested(argc, argv)) {
    if (rank == 0) std::printf("gradfric %s (commit %s)\n", kVersion, kCommit);
  } else {
    const SettledCommandLine settled = settleCommandLine(argc, argv);
    if (!commandLineIsSound(MPI_COMM_WORLD, settled)) {
      status = 2;
    } else {
      adoptCommandLine(settled, argc, argv);
      status = runWithPetsc(settled.arguments, help, body);
    }
  }
  MPI_Finalize();
  return status;
}

}  // namespace gradfric
