#include "gradfric/fem/simulation.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/verlet_ts.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

// PETSc callbacks: exceptions stop at this boundary and become PETSc error codes.
namespace {

PetscErrorCode rhsCallback(TS, PetscReal t, Vec X, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  try {
    static_cast<gradfric::fem::PlateModel*>(ctx)->rhs(t, X, F);
  } catch (const gradfric::PetscCallError& e) {
    SETERRQ(PETSC_COMM_SELF, e.code(), "%s", e.what());
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  PetscFunctionReturn(0);
}

}  // namespace

namespace gradfric::fem {

TS createPlateTS(PlateModel& model, Vec state) {
  registerVerletTS();
  TS ts = nullptr;
  GF_CALL(TSCreate(model.comm(), &ts));
  try {
    GF_CALL(TSSetProblemType(ts, TS_NONLINEAR));
    GF_CALL(TSSetType(ts, TSGFVERLET));
    GF_CALL(TSSetRHSFunction(ts, nullptr, rhsCallback, &model));
    GF_CALL(TSSetTimeStep(ts, model.timeStep()));
    GF_CALL(TSSetMaxTime(ts, 1e30));
    GF_CALL(TSSetMaxSteps(ts, PETSC_MAX_INT));
    GF_CALL(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP));
    GF_CALL(TSSetSolution(ts, state));
    GF_CALL(TSSetFromOptions(ts));
    TSAdapt adapt = nullptr;
    GF_CALL(TSGetAdapt(ts, &adapt));
    GF_CALL(TSAdaptSetType(adapt, TSADAPTNONE));  // fixed step: the stable step is a hard bound
    GF_CALL(TSSetTimeStep(ts, model.timeStep()));
    GF_CALL(TSSetUp(ts));
  } catch (...) {
    TSDestroy(&ts);
    throw;
  }
  return ts;
}

namespace {

// The blow-up monitor and the energy balance of the run (see FemRunResult::energy*).
class Monitor {
public:
  Monitor(PlateModel& model, TS ts, FemRunResult* result) : model_(model), ts_(ts), r_(result) {
    const FemParameters& q = model.params();
    reference_ = q.plate.pressure * q.plate.pressure * q.plate.length * q.plate.length * q.plate.thickness / (2 * q.plate.youngsModulus);  // elastic energy of the plate compressed by p
  }
  void startSliding(Vec state, double kineticBefore) { injected_ += model_.kineticEnergy(state) - kineticBefore; }
  // After every step, with the totals of that step (already summed over ranks).
  void afterStep(long step, double t, Vec state, const ContactTotals& totals, double mu) {
    const FemParameters& q = model_.params();
    if (!std::isfinite(mu)) fail(step, t, "mu(t), the friction force / (p L^2), is not finite");
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
  void check(long step, double t, Vec state) {
    const FemParameters& q = model_.params();
    const double energy = model_.kineticEnergy(state) + model_.elasticEnergy(state);
    const double in = injected_ + pressureWork_ + driveWork_;
    r_->energyTime.push_back(t);
    r_->energy.push_back(energy);
    r_->energyIn.push_back(in);
    if (!std::isfinite(energy))
      fail(step, t, "the kinetic + elastic energy is not finite (a non-finite displacement or velocity)");
    if (energy > q.monitorFactor * (std::max(in, 0.0) + reference_)) {
      char what[300];
      std::snprintf(what, sizeof what,
                    "the kinetic + elastic energy (%.4g J) grows without bound: above %g x (the energy put in, %.4g J, "
                    "+ p^2 L^2 H / 2E = %.4g J)",
                    energy, q.monitorFactor, in, reference_);
      fail(step, t, what);
    }
  }

private:
  [[noreturn]] void fail(long step, double t, const std::string& quantity) {
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
                    "the integrator -ts_type %s is unstable at dt = %.4g s (%.2f of the stable step of gfverlet's "
                    "central difference, which the estimate is for): lower -fem_dt_safety or use -ts_type gfverlet",
                    ts.c_str(), dt, dt / stable);
    else
      std::snprintf(cause, sizeof cause,
                    "dt = %.4g s is %.2f of the stable-step estimate (%.4g s: stiffest element, penalty springs k_n = "
                    "%.3g, k_t = %.3g Pa/m, damping); an extreme penalty, grading or damping setting may need a "
                    "smaller -fem_dt_safety",
                    dt, dt / stable, stable, model_.params().kn, model_.params().kt);
    char where[200];
    std::snprintf(where, sizeof where, "FEM run unstable at step %ld (t = %.6g s, %s): ", step, t,
                  model_.phase() == Phase::Pressure ? "pressure step" : "sliding step");
    throw BlowUpError(std::string(where) + quantity + ". Likely cause: " + cause + ". Run stopped, no results written.");
  }

  PlateModel& model_;
  TS ts_;
  FemRunResult* r_;
  double reference_ = 0, injected_ = 0, pressureWork_ = 0, driveWork_ = 0;
  double lastZ_ = 0, lastP_ = 0, lastPower_ = 0;
  bool started_ = true, sliding_ = false;  // the run starts at rest, Z = 0, p = 0
};

}  // namespace

FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer) {
  const FemParameters& q = model.params();
  FemRunResult r;
  r.dt = model.timeStep();
  r.stableDt = model.stableTimeStep();
  OwnedVec X(model.createState());
  OwnedTS ts(createPlateTS(model, X));
  const double normal = q.plate.pressure * q.plate.length * q.plate.length;

  // Step 1: pressure ramp and hold.
  model.setPhase(Phase::Pressure);
  double t0 = MPI_Wtime();
  const double tSettle = q.rampTime + q.settleTime;
  PetscReal t = 0;
  Monitor monitor(model, ts, &r);
  Vec state = nullptr;
  while (t < tSettle - 0.5 * r.dt) {
    GF_CALL(TSStep(ts));
    model.commitContact();
    GF_CALL(TSGetTime(ts, &t));
    GF_CALL(TSGetSolution(ts, &state));
    ++r.steps;
    const ContactTotals totals = model.contactTotals();
    monitor.afterStep(r.steps, t, state, totals, 0.0);
  }
  r.settledNormalForce = model.contactTotals().fn / normal;
  if (q.verbose)
    GF_CALL(PetscPrintf(model.comm(), "  step 1 done: t = %.4e s, %ld steps, normal force %.6f p L^2\n", t, r.steps,
                        r.settledNormalForce));
  r.wallPressure = MPI_Wtime() - t0;

  // Step 2: the top slides at v.
  GF_CALL(TSGetSolution(ts, &state));
  const double kineticBefore = model.kineticEnergy(state);
  model.startSliding(state);
  monitor.startSliding(state, kineticBefore);
  verletInvalidate(ts);
  r.slideStart = t;
  t0 = MPI_Wtime();
  double muMax = -1;
  for (;;) {
    GF_CALL(TSStep(ts));
    model.commitContact();
    GF_CALL(TSGetTime(ts, &t));
    GF_CALL(TSGetSolution(ts, &state));
    ++r.steps;
    const double ts_ = t - r.slideStart;
    const ContactTotals totals = model.contactTotals();
    const double mu = std::hypot(totals.fx, totals.fy) / normal;
    r.time.push_back(ts_);
    r.mu.push_back(mu);
    r.normalForce.push_back(totals.fn / normal);
    r.forceX.push_back(totals.fx);
    r.forceY.push_back(totals.fy);
    monitor.afterStep(r.steps, t, state, totals, mu);
    if (r.firstSlipTime < 0 && totals.slip > 0) r.firstSlipTime = ts_;
    if (mu > muMax) {
      muMax = mu;
      r.peakTime = ts_;
      r.peakConfirmed = false;
    } else if (mu < 0.95 * muMax) {
      r.peakConfirmed = true;
    }
    if (observer) observer(ts_, state);
    if (q.verbose && r.time.size() % 500 == 0)
      GF_CALL(PetscPrintf(model.comm(), "  sliding: t - t0 = %.4e s, mu = %.5f, slipping nodes %lld, sticking %lld\n", ts_,
                          mu, totals.slip, totals.stick));
    const double windowEnd = r.peakTime + q.windowStart + q.windowLength;
    if (q.stopWhenKnown && r.peakConfirmed && ts_ >= windowEnd) break;
    if (ts_ >= q.slideTime - 0.5 * r.dt) break;
  }
  r.wallSliding = MPI_Wtime() - t0;
  if (r.steps % q.monitorEvery != 0) monitor.check(r.steps, t, state);  // the final state too
  r.muS = muMax;
  const double w0 = r.peakTime + q.windowStart, w1 = w0 + q.windowLength;
  double sum = 0;
  long n = 0;
  for (std::size_t i = 0; i < r.time.size(); ++i)
    if (r.time[i] >= w0 && r.time[i] <= w1) {
      sum += r.mu[i];
      ++n;
    }
  r.windowComplete = r.peakConfirmed && !r.time.empty() && r.time.back() >= w1 - r.dt;
  r.muK = n ? sum / n : std::nan("");
  return r;
}

}  // namespace gradfric::fem
