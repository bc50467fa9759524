#include "gradfric/fem/energy_monitor.hpp"

#include "gradfric/fem/term_registry.hpp"

#include <cmath>
#include <cstdio>

namespace gradfric::fem {

EnergyMonitor::EnergyMonitor(PlateModel& model, TS ts, EnergyRecord* record)
    : model_(model), ts_(ts), record_(record) {
  const FemParameters& q = model.params();
  // The load on the plane: p, plus the optional terms' dead loads (the weight rho g H with
  // -fem_gravity). A plate under a small p would otherwise be stopped for the energy its weight
  // gave it (not in the energy put in) or for its friction, which mu(t) = |F|/(p L^2) counts over
  // p L^2 alone.
  const DeadLoads dead = deadLoadsOf(q);
  const double load = q.plate.pressure + dead.pressure;
  // The elastic energy of the plate compressed by the load: the scale before any work is done.
  const double reference = load * load * q.plate.length * q.plate.length *
                           q.plate.thickness / (2 * q.plate.youngsModulus);
  bound_ = EnergyBound{q.monitorFactor, reference};
  muCeiling_ = 2.0 * model.contact().largestStaticCoefficient() * (load / q.plate.pressure);
  if (!dead.symbols.empty())
    muCeilingText_ = " (twice the largest local mu_s times (p" + dead.symbols + ")/p, " + dead.shares + ")";
}

void EnergyMonitor::startSliding(Vec state, double kineticBefore) {
  injected_ += model_.kineticEnergy(state) - kineticBefore;
}

void EnergyMonitor::afterStep(long step, double t, Vec state, const ContactTotals& totals, double mu) {
  const FemParameters& q = model_.params();
  // mu(t) cannot exceed the largest local mu_s but by a dynamic overshoot: twice that is a blow-up.
  const std::string muProblem = frictionViolation(mu, muCeiling_);
  if (!muProblem.empty()) fail(step, t, muProblem + muCeilingText_);
  if (!std::isfinite(totals.fn)) fail(step, t, "the contact normal force is not finite");
  if (!std::isfinite(totals.topZ)) fail(step, t, "the top surface's vertical displacement is not finite");
  const double p = model_.pressureAt(t);
  if (started_) pressureWork_ -= 0.5 * (p + lastP_) * (totals.topZ - lastZ_);
  started_ = true;
  lastZ_ = totals.topZ;
  lastP_ = p;
  if (model_.phase() == Phase::Sliding) {
    const double theta = q.plate.slidingAngle * M_PI / 180.0;
    const double power = q.plate.velocity * (totals.driveX * std::cos(theta) + totals.driveY * std::sin(theta));
    driveWork_ += 0.5 * (power + (sliding_ ? lastPower_ : power)) * model_.timeStep();
    lastPower_ = power;
    sliding_ = true;
  }
  if (step % q.monitorEvery == 0) check(step, t, state);
}

void EnergyMonitor::check(long step, double t, Vec state) {
  const double energy = model_.kineticEnergy(state) + model_.elasticEnergy(state);
  const double in = injected_ + pressureWork_ + driveWork_;
  record_->time.push_back(t);
  record_->energy.push_back(energy);
  record_->energyIn.push_back(in);
  record_->dissipated.push_back(model_.dissipatedEnergy());
  const std::string energyProblem =
      bound_.violation(energy, in, "the energy put in");
  if (!energyProblem.empty()) fail(step, t, energyProblem);
}

void EnergyMonitor::archive(StateArchive& a) {
  a.field("energy.injected", injected_);
  a.field("energy.pressureWork", pressureWork_);
  a.field("energy.driveWork", driveWork_);
  a.field("energy.lastZ", lastZ_);
  a.field("energy.lastP", lastP_);
  a.field("energy.lastPower", lastPower_);
  a.field("energy.started", started_);
  a.field("energy.sliding", sliding_);
  a.field("energy.time", record_->time);
  a.field("energy.energy", record_->energy);
  a.field("energy.energyIn", record_->energyIn);
  a.field("energy.dissipated", record_->dissipated);
}

void EnergyMonitor::fail(long step, double t, const std::string& quantity) {
  TSType type = nullptr;
  TSGetType(ts_, &type);
  const std::string ts = type ? type : "?";
  const double dt = model_.timeStep(), stable = model_.stableTimeStep();
  char cause[600];
  if (dt > stable)
    std::snprintf(cause, sizeof cause,
                  "the time step dt = %.4g s is above the stable step %.4g s (accepted only because of "
                  "-fem_dt_check false): use dt <= %.4g s or leave -fem_dt unset",
                  dt, stable, stable);
  else if (ts != "gfverlet")
    std::snprintf(cause, sizeof cause,
                  "the integrator -fem_ts_type %s is unstable at dt = %.4g s (%.2f of the stable step of gfverlet's "
                  "central difference, which the estimate is for): lower -fem_dt_safety or use -fem_ts_type gfverlet",
                  ts.c_str(), dt, dt / stable);
  else
    std::snprintf(cause, sizeof cause,
                  "dt = %.4g s is %.2f of the stable-step estimate (%.4g s: stiffest element, penalty springs k_n = "
                  "%.3g, k_t = %.3g Pa/m, damping); an extreme penalty, grading or damping setting may need a "
                  "smaller -fem_dt_safety",
                  dt, dt / stable, stable, model_.params().kn, model_.params().kt);
  const std::string phase = model_.phase() == Phase::Pressure ? " (pressure step)" : " (sliding step)";
  throw NumericalInstability("FEM", quantity + phase, t, step, cause);
}

}  // namespace gradfric::fem
