#pragma once
// The -friction_ options: how both models measure friction (friction_history.hpp).
#include "gradfric/core/options.hpp"
#include "gradfric/physics/friction_history.hpp"

#include <string>
#include <vector>

namespace gradfric {

// A caller's defaults for the measurement: the steady kinetic window (the SBM keeps its fixed
// window: tolerance 0) and what a run determines (a calibration asks mu_s only). The options
// override them; the caller never writes the options database.
struct MeasurementDefaults {
  double steadyTolerance = 0.0;     // -friction_muk_steady_tol; 0: the fixed window
  double latestDelayFactor = 0.5;   // -friction_muk_latest_delay in t_load
  std::vector<std::string> observables = {"mu_s", "mu_k", "first_slip"};  // -friction_observables
};

// loadingTime: the model's time to load the uniform plate to its static threshold (paper Eq. 2;
// the SBM with its l_z, the FEM with H), the scale of the derived defaults. The names the models
// used before (-sbm_peak_drop, -fem_kinetic_window_start, ...) are refused with the new spelling.
FrictionMeasurement readFrictionMeasurement(MPI_Comm comm, RunParameters* record, double loadingTime,
                                            const MeasurementDefaults& defaults = {});

}  // namespace gradfric
