#pragma once
// The FEM's blow-up monitor and energy balance (FemRunResult::energy*): finite mu(t), normal force
// and top displacement every step; every -fem_monitor_every steps, kinetic + elastic energy
// bounded by the energy put in (pressure work, slider work, the kinetic energy given to the top at
// the start of sliding). Throws BlowUpError naming the quantity, the step, the time and the cause.
#include "gradfric/fem/plate_model.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace gradfric::fem {

// Thrown (on every rank: the monitored values are global) when a run goes unstable: a non-finite
// mu(t), normal force or state, or energy growing without bound. what() names the quantity, the
// step and time, and the likely cause.
class BlowUpError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct EnergyRecord {
  std::vector<double> time, energy, energyIn;  // see FemRunResult
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

private:
  [[noreturn]] void fail(long step, double t, const std::string& quantity);

  PlateModel& model_;
  TS ts_;
  EnergyRecord* record_;
  double reference_ = 0, injected_ = 0, pressureWork_ = 0, driveWork_ = 0;
  double lastZ_ = 0, lastP_ = 0, lastPower_ = 0;
  bool started_ = true, sliding_ = false;  // the run starts at rest, Z = 0, p = 0
};

}  // namespace gradfric::fem
