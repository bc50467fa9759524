#pragma once
// The paper's two-step FEM experiment on a PlateModel: pressure ramp and hold (step 1), then the
// top surface slides at v (step 2); mu(t), mu_s, the peak time, mu_k over the kinetic window.
#include "gradfric/fem/plate_model.hpp"

#include <functional>
#include <stdexcept>
#include <vector>

namespace gradfric::fem {

struct FemRunResult {
  // mu(t) = |total tangential contact force| / (p L^2), time measured from the start of sliding.
  std::vector<double> time, mu, normalForce;  // every step of step 2; normalForce is F_n / (p L^2)
  std::vector<double> forceX, forceY;          // total tangential contact force components [N]
  double muS = 0;            // global static coefficient: max of mu(t)
  double peakTime = 0;       // time of the peak after the start of sliding [s]
  double firstSlipTime = -1; // first node slipping after the start of sliding [s]
  double muK = 0;            // mean of mu(t) over the kinetic window
  bool peakConfirmed = false, windowComplete = false;
  double slideStart = 0;     // absolute time of the start of sliding [s]
  double settledNormalForce = 0;  // total contact normal force / (p L^2) at the end of step 1
  double dt = 0, stableDt = 0;
  long steps = 0;
  double wallPressure = 0, wallSliding = 0;  // seconds
  // Energy balance, sampled by the blow-up monitor every -fem_monitor_every steps and at the end:
  // time since the start of the run [s]; kinetic + elastic energy of the plate [J]; energy put in
  // [J] = work of the pressure (-integral p dZ, Z = sum of area * u_z over the top) + work of the
  // slider (integral F . v dt) + the kinetic energy given to the top at the start of sliding.
  // Friction, damping and the penalty springs' own energy make the difference (energy <= put in,
  // up to the integrator's O(dt^2) energy error).
  std::vector<double> energyTime, energy, energyIn;
};

// Thrown (on every rank: the monitored values are global) when a run goes unstable: a non-finite
// mu(t), normal force or state, or energy growing without bound. what() names the quantity, the
// step and time, and the likely cause.
class BlowUpError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Called after each step of step 2 with the time since the start of sliding and the state.
using StepObserver = std::function<void(double tSliding, Vec state)>;

// Runs the experiment on a fresh TS (type gfverlet unless -ts_type says otherwise). Throws
// BlowUpError when the monitor sees the run go unstable (no result is returned, nothing written).
FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer = {});

// Builds the TS used by the experiment and the tests: fixed step model.timeStep(), RHS of the
// model, -ts_ options applied. The caller owns the TS.
TS createPlateTS(PlateModel& model, Vec state);

}  // namespace gradfric::fem
