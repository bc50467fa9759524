#pragma once
// The options of one FEM scene, read and checked the same way by gradfric-fem and the FEM
// benchmarks: the grading, the plate record, the -fem_ parameters and the -field_ maps, then the
// checks that need all of them (fields against the mesh, the -ts_ options, misspellings, the run
// length and the stable step).
#include "gradfric/core/options.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace gradfric::fem {

struct FemScene {
  Grading grading;  // with the -field_ maps (grading.fields)
  Plate plate;
  FemParameters params;  // derived defaults resolved
};

// Reads -grading_, -plate_, -fem_ and -field_ (in that order: the -help listing follows it).
FemScene readFemScene(MPI_Comm comm, RunParameters* record);
// The checks after every option of the program was read: the fields against the mesh, the -ts_
// options, unused or misspelt options under the scene's prefixes and extraPrefixes, the run length
// and the time step (InputError on every rank alike).
void checkFemScene(MPI_Comm comm, const FemScene& scene, RunParameters* record,
                   const std::vector<std::string>& extraPrefixes = {});
// Both, for programs whose own options were read before: nullopt after -help.
std::optional<FemScene> readCheckedFemScene(MPI_Comm comm, RunParameters* record,
                                            const std::vector<std::string>& extraPrefixes = {});

}  // namespace gradfric::fem
