#pragma once
// FEM runs a design already has (-design_reuse), taken instead of running them again:
// - the evaluations of earlier design files of the same scene: a FEM run on an undispersed
//   surface is deterministic, so a run read back is the run, and the design is the same, bit for
//   bit, as if it had run them;
// - the rows of a FEM study table (docs/fem_study.tsv, "study" for the one the bars come from)
//   whose scene is the design's plate at the row's grading amplitude, or its non-graded plate:
//   those keep 6 decimals, so the design can differ from a fresh one in the 7th
// (docs/design.md, "Reusing earlier runs").
#include "gradfric/core/options.hpp"
#include "gradfric/design/flutter_exposure.hpp"

#include <mpi.h>

#include <array>
#include <string>
#include <vector>

namespace gradfric::design {

struct Problem;

struct KnownFemRun {
  std::array<int, 3> mesh{};  // nx, ny, nz
  bool reference = false;     // the non-graded plate (x empty)
  std::vector<double> x;      // the free parameters' values
  double muStatic = 0.0;
  FlutterExposure flutter;
};

// Collective: the FEM runs of the files `paths` (read on rank 0, broadcast). A design file must
// be a design with -design_model fem of the same free parameters whose every option that a FEM
// run depends on equals this run's (record): all but the -design_* (search, target, tolerance,
// bounds), -sbm_* (the spring blocks' model-form check), the -fem_* mesh (a run keeps its own)
// and the output options. A study table serves a design of grading_delta; its rows of other
// scenes are passed over. Else InputError naming -design_reuse, the file and the first option
// that differs, on every rank alike.
std::vector<KnownFemRun> readKnownFemRuns(MPI_Comm comm, const std::vector<std::string>& paths, const Problem& problem,
                                          const RunParameters& record);

// The option names a FEM run of a design does not depend on (without the dash): compared by
// readKnownFemRuns only for the others.
bool femRunIndependentOf(const std::string& option);

}  // namespace gradfric::design
