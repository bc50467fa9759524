// The experiment as one TSSolve (PETSc's way, as PyLith's TimeDependent):
//  - pre-step: the start of sliding (step 2) once step 1 (ramp + settle) is over: the top's
//    tangential velocity is set and the TS told to restart its step (TSRestartStep);
//  - post-step: each layer's post-step (the contact state of the accepted step committed, the
//    damping's work), then the observers: the step's totals are summed over ranks, mu(t) fed to
//    the shared FrictionHistory and its stop rule applied
//    (TS_CONVERGED_USER once the -friction_observables are known, or at the end of the sliding
//    time). The rule must see this step's mu: a monitor runs after the post-step and TSStep resets
//    the converged reason, so only the post-step can stop the solve at this step. For the
//    observer, "every site slipped" = every bottom node slipped or lost contact at least once
//    since the start of sliding (in a plate with a 0.1 E0 band, nodes there can stay stuck for
//    many t_load while the plate shears above them: the peak is then not confirmed, see
//    tests/fem/test_fem_hard_grading.cpp); the first slip = the first step with a node slipping;
//  - monitors (TSMonitorSet): the blow-up / energy monitor, the snapshot output (StepObserver) and
//    the progress lines; -fem_ts_monitor and any other -fem_ts_ monitor run alongside.
#include "gradfric/fem/simulation.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/pressed_equilibrium.hpp"
#include "gradfric/physics/friction_laws.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace gradfric::fem {

namespace {

class Experiment {
public:
  Experiment(PlateModel& model, const StepObserver& observer)
      : model_(model),
        observer_(observer),
        q_(model.params()),
        normal_(q_.plate.pressure * q_.plate.length * q_.plate.length),
        history_(q_.measurement, normal_, model.timeStep()) {
    r_.dt = model.timeStep();
    r_.stableDt = model.stableTimeStep();
  }

  FemRunResult run() {
    OwnedVec X(model_.createState());
    OwnedTS ts(createPlateTS(model_, X));
    EnergyRecord energyRecord;
    monitor_.emplace(model_, ts.get(), &energyRecord);
    model_.setPhase(Phase::Pressure);
    GF_CALL(TSSetApplicationContext(ts, this));
    GF_CALL(TSSetPreStep(ts, preStep));
    GF_CALL(TSSetPostStep(ts, postStep));
    GF_CALL(TSMonitorSet(ts, energyMonitor, this, nullptr));
    if (observer_) GF_CALL(TSMonitorSet(ts, snapshotMonitor, this, nullptr));
    if (q_.verbose) GF_CALL(TSMonitorSet(ts, progressMonitor, this, nullptr));
    wall0_ = MPI_Wtime();
    if (q_.staticPressureStep) startFromPressedEquilibrium(X);
    solvePlateTS(ts);
    if (model_.phase() == Phase::Sliding)
      r_.wallSliding = MPI_Wtime() - wall0_;
    else
      r_.wallPressure = MPI_Wtime() - wall0_;
    TSConvergedReason reason = TS_CONVERGED_ITERATING;
    GF_CALL(TSGetConvergedReason(ts, &reason));
    r_.stoppedByTS = reason != TS_CONVERGED_USER;
    PetscReal t = 0;
    Vec state = nullptr;
    GF_CALL(TSGetTime(ts, &t));
    GF_CALL(TSGetSolution(ts, &state));
    if (r_.steps % q_.monitorEvery != 0) monitor_->check(r_.steps, t, state);  // the final state too
    r_.friction = history_.summary();
    r_.resolution = checkInterfaceResolution(model_, r_.friction.peakTime);
    r_.energyTime = std::move(energyRecord.time);
    r_.energy = std::move(energyRecord.energy);
    r_.energyIn = std::move(energyRecord.energyIn);
    r_.energyDissipated = std::move(energyRecord.dissipated);
    return std::move(r_);
  }

private:
  struct Sample {
    long step = -1;
    ContactTotals totals;
    double mu = 0.0;
  };

  static Experiment& of(TS ts) {
    void* ctx = nullptr;
    GF_CALL(TSGetApplicationContext(ts, &ctx));
    return *static_cast<Experiment*>(ctx);
  }

  static PetscErrorCode preStep(TS ts) {
    return guardedCallback([&] { of(ts).startSlidingWhenSettled(ts); });
  }
  static PetscErrorCode postStep(TS ts) {
    return guardedCallback([&] {
      const LogEventScope timed(femLogEvents().postStep);
      GF_CALL(layersPostStep(ts));  // the layers first, then the observers
      of(ts).afterStep(ts);
    });
  }
  static PetscErrorCode energyMonitor(TS, PetscInt step, PetscReal t, Vec X, void* ctx) {
    return guardedCallback([&] {
      auto* e = static_cast<Experiment*>(ctx);
      if (!e->sampled(step)) return;
      const LogEventScope timed(femLogEvents().monitor);
      e->monitor_->afterStep(step, t, X, e->sample_.totals, e->sample_.mu);
    });
  }
  static PetscErrorCode snapshotMonitor(TS, PetscInt step, PetscReal t, Vec X, void* ctx) {
    return guardedCallback([&] {
      auto* e = static_cast<Experiment*>(ctx);
      if (e->sampled(step) && e->model_.phase() == Phase::Sliding) e->observer_(t - e->r_.slideStart, X);
    });
  }
  static PetscErrorCode progressMonitor(TS, PetscInt step, PetscReal t, Vec, void* ctx) {
    return guardedCallback([&] {
      auto* e = static_cast<Experiment*>(ctx);
      if (!e->sampled(step) || e->model_.phase() != Phase::Sliding || e->r_.time.size() % 500 != 0) return;
      // The wall time left is a bound: the run stops earlier once its observables are known.
      const double tSliding = t - e->r_.slideStart, wall = MPI_Wtime() - e->wall0_;
      const double left = tSliding > 0 ? wall * std::max(0.0, e->q_.slideTime - tSliding) / tSliding : 0.0;
      GF_CALL(PetscPrintf(e->model_.comm(),
                          "  sliding: t - t0 = %.4e s, mu = %.5f, slipping nodes %lld, sticking %lld; wall %.0f s, "
                          "at most %.0f s left\n",
                          tSliding, e->sample_.mu, e->sample_.totals.slip, e->sample_.totals.stick, wall, left));
    });
  }

  // Monitors act on steps the post-step has sampled (not on the initial state, step 0).
  bool sampled(PetscInt step) const { return step > 0 && step == sample_.step; }

  void startSlidingWhenSettled(TS ts) {
    if (model_.phase() != Phase::Pressure) return;
    PetscReal t = 0;
    GF_CALL(TSGetTime(ts, &t));
    if (!model_.protocol().settled(t, r_.dt)) return;
    r_.settledNormalForce = model_.contactTotals().fn / normal_;
    if (q_.verbose)
      GF_CALL(PetscPrintf(model_.comm(), "  step 1 done: t = %.4e s, %ld steps, normal force %.6f p L^2\n", t,
                          r_.steps, r_.settledNormalForce));
    r_.wallPressure = MPI_Wtime() - wall0_;
    Vec state = nullptr;
    GF_CALL(TSGetSolution(ts, &state));
    const double kineticBefore = model_.kineticEnergy(state);
    model_.startSliding(state);
    monitor_->startSliding(state, kineticBefore);
    GF_CALL(TSRestartStep(ts));  // the solution changed outside the integrator
    r_.slideStart = t;
    wall0_ = MPI_Wtime();
  }

  // -fem_pressure_step static: step 1 without time steps: the pressed equilibrium, the plate at
  // rest, then sliding from t = 0. Where it does not hold (penalty contact only; a node that would
  // slip or lift off), the dynamic step runs as usual.
  void startFromPressedEquilibrium(Vec X) {
    std::string why = "only with the penalty contact";
    if (q_.contact && q_.contactMethod == ContactMethod::Penalty) {
      const PressedEquilibrium e = solvePressedEquilibrium(model_, X);
      r_.pressureIterations = e.iterations;
      if (e.holds) {
        r_.staticPressureStep = true;
        r_.settledNormalForce = e.normalForce / normal_;
        r_.wallPressure = MPI_Wtime() - wall0_;
        if (q_.verbose)
          GF_CALL(PetscPrintf(model_.comm(),
                              "  step 1 done (static): %d CG iterations (residual %.1e), normal force %.6f p L^2\n",
                              e.iterations, e.residual, r_.settledNormalForce));
        model_.startSliding(X);
        monitor_->startSliding(X, 0.0);
        r_.slideStart = 0.0;
        wall0_ = MPI_Wtime();
        return;
      }
      why = e.why;
    }
    GF_CALL(PetscPrintf(model_.comm(), "  static pressure step not used (%s): the dynamic step runs\n", why.c_str()));
  }

  void afterStep(TS ts) {
    PetscInt step = 0;
    PetscReal t = 0;
    GF_CALL(TSGetStepNumber(ts, &step));
    GF_CALL(TSGetTime(ts, &t));
    r_.steps = step;
    sample_.step = step;
    sample_.totals = model_.contactTotals();
    sample_.mu = 0.0;
    if (model_.phase() != Phase::Sliding) return;
    const double tSliding = t - r_.slideStart;
    const ContactTotals& totals = sample_.totals;
    // First slip: a node slipping (not one losing contact); every site: slipped or lost contact.
    const double mu = history_.observe(tSliding, totals.fx, totals.fy, totals.slip > 0,
                                       totals.everSlipped == totals.nodes);
    sample_.mu = mu;
    if (recordOnset_) model_.recordOnset(tSliding);
    if (q_.measurement.firstSlipMap) model_.recordFirstSlips(tSliding);
    // The damping of the sliding plate starts at the confirmed peak (mu_s is then the undamped
    // run's), or as -fem_peak_damping_start says (loading_protocol.hpp).
    const bool pastPeak =
        model_.protocol().peakDampingDue(history_.peakConfirmed(), totals.slip > 0, mu, history_.peak());
    if (pastPeak && !model_.peakDampingOn() && model_.startPeakDamping()) {
      r_.peakDampingStart = tSliding;
      if (q_.verbose)
        GF_CALL(PetscPrintf(model_.comm(), "  peak confirmed at t - t0 = %.4e s: damping while sliding on\n", tSliding));
    }
    r_.time.push_back(tSliding);
    r_.mu.push_back(mu);
    r_.normalForce.push_back(totals.fn / normal_);
    r_.forceX.push_back(totals.fx);
    r_.forceY.push_back(totals.fy);
    const bool known = q_.stopWhenKnown && history_.known();
    if (known || model_.protocol().slideOver(tSliding, r_.dt)) GF_CALL(TSSetConvergedReason(ts, TS_CONVERGED_USER));
  }

  PlateModel& model_;
  const StepObserver& observer_;
  const FemParameters& q_;
  FemRunResult r_;
  std::optional<EnergyMonitor> monitor_;
  double normal_;
  FrictionHistory history_;
  Sample sample_;
  double wall0_ = 0;
  bool recordOnset_ = isStateLaw(q_.frictionLaw);  // for the interface resolution check
};

}  // namespace

FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer) {
  Experiment experiment(model, observer);
  return experiment.run();
}

}  // namespace gradfric::fem
