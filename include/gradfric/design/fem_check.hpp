#pragma once
// The design's FEM runs (gradfric-fem's library: the same plate, grading and fields, the -fem_*
// mesh and numerics, a reduced mesh allowed), each to its confirmed static peak: the evaluations
// of -design_model fem and the check of -design_verify_fem, both through FemEvaluator.
#include "gradfric/core/options.hpp"
#include "gradfric/design/flutter_exposure.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <mpi.h>

#include <memory>
#include <optional>
#include <vector>

namespace gradfric::design {

struct FemCheck {
  fem::FemParameters parameters;
  RunParameters record;  // the -fem_* options (their own record: the FEM derives other defaults)
};

// Collective: reads the -fem_* and -ts_* options (also under -help).
std::shared_ptr<FemCheck> readFemCheck(MPI_Comm comm, const Plate& plate);

// Collective, before any work: refuses a plate of the family the mesh cannot carry or an endless
// run, at each of `corners`.
void checkFemCheck(const FemCheck& check, const std::vector<Grading>& corners);

// One FEM run of a plate of the family to its confirmed static peak.
struct FemRun {
  double muStatic = 0.0;
  bool peakConfirmed = false;
  double wallSeconds = 0.0;
  FlutterExposure flutter;  // the nodes that slid at mu(theta) > 1 before the peak
  bool reused = false;      // taken from -design_reuse (a design file or the study table), not run
};

// Collective over comm: the design's one way to run the FEM (evaluations and checks alike).
FemRun runFemPlate(MPI_Comm comm, const FemCheck& check, const Grading& grading);

// -design_verify_fem: the FEM at the spring blocks' design (FemEvaluator::check).
struct FemVerification {
  FemRun design;
  std::optional<FemRun> reference;  // the FEM's own non-graded plate, of a variation target
  int cells = 0;
};

}  // namespace gradfric::design
