#pragma once
// The FEM's blow-up monitor and energy balance (FemRunResult::energy*), on the shared stability
// layer (physics/stability.hpp): every step mu(t) finite and below twice the largest local mu_s
// (frictionViolation, as the SBM; times (p + dead loads)/p, the optional terms' dead loads, as the
// weight rho g H with -fem_gravity: term_registry.hpp), the normal force and the top displacement
// finite; every -fem_monitor_every steps, kinetic + elastic energy bounded by -fem_monitor_factor x
// (the energy put in + p^2 L^2 H / 2E, p plus the dead loads) (EnergyBound); the energy put in is
// the pressure work, the slider work and the kinetic energy given to the top at the start of
// sliding. A violation throws NumericalInstability naming the quantity, the time, the step and the
// likely cause.
#include "gradfric/fem/plate_model.hpp"
#include "gradfric/physics/stability.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

struct EnergyRecord {
  std::vector<double> time, energy, energyIn, dissipated;  // see FemRunResult
};

class EnergyMonitor {
public:
  EnergyMonitor(PlateModel& model, TS ts, EnergyRecord* record);
  // At the start of sliding, with the kinetic energy before the top was set in motion.
  void startSliding(Vec state, double kineticBefore);
  // After every step, with the totals of that step (already summed over ranks).
  void afterStep(long step, double t, Vec state, const ContactTotals& totals, double mu);
  // The energy balance now (every monitorEvery steps and at the end of the run).
  void check(long step, double t, Vec state);
  // Saves or restores the work counted so far and the record (checkpoints).
  void archive(StateArchive& a);

private:
  [[noreturn]] void fail(long step, double t, const std::string& quantity);

  PlateModel& model_;
  TS ts_;
  EnergyRecord* record_;
  EnergyBound bound_;
  std::string muCeilingText_ = " (twice the largest local mu_s)";
  double muCeiling_ = 0, injected_ = 0, pressureWork_ = 0, driveWork_ = 0;
  double lastZ_ = 0, lastP_ = 0, lastPower_ = 0;
  bool started_ = true, sliding_ = false;  // the run starts at rest, Z = 0, p = 0
};

}  // namespace gradfric::fem
