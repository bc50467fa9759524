#pragma once
// -design_verify_fem: the design's surface in the finite-element model (gradfric-fem's library:
// the same plate, grading and fields, the -fem_* mesh and numerics, a reduced mesh allowed), run
// to its confirmed static peak and printed beside the spring-block values.
#include "gradfric/core/options.hpp"
#include "gradfric/design/flutter_exposure.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <mpi.h>

#include <limits>
#include <memory>
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

struct FemVerification {
  double muStatic = 0.0;
  bool peakConfirmed = false;
  double wallSeconds = 0.0;
  int cells = 0;
  FlutterExposure flutter;  // the nodes that slid at mu(theta) > 1 before the peak
  // The FEM's own non-graded plate, the reference of a variation target (else not run: NaN).
  double referenceMuStatic = std::numeric_limits<double>::quiet_NaN();
  bool referenceConfirmed = false;
  double referenceWallSeconds = 0.0;
};

// Collective over comm. reference: the non-graded plate, run too when given (a variation target).
FemVerification runFemCheck(MPI_Comm comm, const FemCheck& check, const Grading& grading,
                            const Grading* reference = nullptr);

}  // namespace gradfric::design
