#pragma once
// The -friction_ options: how both models measure friction (friction_history.hpp).
#include "gradfric/core/options.hpp"
#include "gradfric/physics/friction_history.hpp"

namespace gradfric {

// A model's defaults for the steady kinetic window (the SBM keeps its fixed window: tolerance 0).
struct KineticWindowDefaults {
  double steadyTolerance = 0.0;     // -friction_muk_steady_tol; 0: the fixed window
  double latestDelayFactor = 0.5;   // -friction_muk_latest_delay in t_load
};

// loadingTime: the model's time to load the uniform plate to its static threshold (paper Eq. 2;
// the SBM with its l_z, the FEM with H), the scale of the derived defaults. The names the models
// used before (-sbm_peak_drop, -fem_kinetic_window_start, ...) are refused with the new spelling.
FrictionMeasurement readFrictionMeasurement(MPI_Comm comm, RunParameters* record, double loadingTime,
                                            const KineticWindowDefaults& window = {});

}  // namespace gradfric
