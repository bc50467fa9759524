#pragma once
// The paper's two-step FEM experiment on a PlateModel: pressure ramp and hold (step 1), then the
// top surface slides at v (step 2); mu(t) observed by the shared FrictionHistory (the rule of both
// models: peak confirmed after a drop or a hold once every bottom node slipped or lost contact).
// Driven by one TSSolve (see simulation.cpp for the callbacks).
#include "gradfric/fem/checkpoint.hpp"
#include "gradfric/fem/energy_monitor.hpp"
#include "gradfric/fem/interface_resolution.hpp"
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/fem/plate_ts.hpp"
#include "gradfric/physics/friction_history.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace gradfric::fem {

struct FemRunResult {
  // mu(t) = |total tangential contact force| / (p L^2), time measured from the start of sliding.
  std::vector<double> time, mu, normalForce;  // every step of step 2; normalForce is F_n / (p L^2)
  std::vector<double> forceX, forceY;          // total tangential contact force components [N]
  // The shared observer's result (physics/friction_history.hpp), times from the start of sliding:
  // mu_s, its time and confirmation, mu_k over the kinetic window, the first slip (some bottom
  // node slipping), the history sampled every -friction_history_interval with F_x, F_y.
  FrictionSummary friction;
  bool stoppedByTS = false;  // the TS's own limits (-fem_ts_max_steps, -fem_ts_max_time) ended the run first
  double slideStart = 0;     // absolute time of the start of sliding [s]
  double settledNormalForce = 0;  // total contact normal force / (p L^2) at the end of step 1
  bool staticPressureStep = false;  // step 1 was the pressed equilibrium (no time steps)
  int pressureIterations = 0;       // its CG iterations (-fem_pressure_step static)
  double peakDampingStart = -1;   // time after the start of sliding the peak damping began [s]; < 0: never
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
  // At the same samples: the energy the contact forces and the damping took from the plate [J]
  // (PlateModel::dissipatedEnergy); energy + dissipated = energy put in closes the balance.
  std::vector<double> energyDissipated;
  // Whether the law's weakening length was resolved (D_c, kappa, elastic slip, slip per step,
  // the measured process zone): printed and stored next to mu_s.
  InterfaceResolution resolution;
  // Checkpoints (checkpoint.hpp): written by this process, their wall time [s], the step resumed from (-1:
  // none), and the signal that stopped the run after its last checkpoint (0: it ran to its end).
  int checkpoints = 0;
  double checkpointWall = 0.0;
  long resumedFromStep = -1;
  int interruptedBy = 0;
};

// Called after each step of step 2 with the time since the start of sliding and the state.
using StepObserver = std::function<void(double tSliding, Vec state)>;

// A run's checkpoints: where and how often, the checkpoint it resumes from, and the state of its
// observer (the output's pressure-response sums), saved and restored with the rest.
struct CheckpointPlan {
  CheckpointSettings settings;  // settings.path empty: none
  std::optional<CheckpointHeader> resumeFrom;
  std::function<void(StateArchive&)> archiveObserver;
};

// Runs the experiment on a fresh TS (createPlateTS: -fem_ts_ options apply, -fem_ts_monitor,
// -fem_ts_view, -fem_ts_max_steps, -fem_ts_type ...). Throws NumericalInstability when the monitor sees the run go unstable (no
// result is returned, nothing written).
FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer = {},
                                const CheckpointPlan* checkpoints = nullptr);

}  // namespace gradfric::fem
