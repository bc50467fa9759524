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
//  - checkpoints (checkpoint.hpp): at the end of the post-step, every -checkpoint_interval of
//    rank 0's wall time or after SIGINT/SIGTERM (one reduction of the flags per step on more than
//    one rank), the state between two steps. The step's monitors have not run yet: a resumed run's
//    TSSolve runs them first, on the restored step (TSSolve monitors its initial state), so every
//    monitor sees every step once;
//  - monitors (TSMonitorSet): the blow-up / energy monitor, the snapshot output (StepObserver) and
//    the progress lines; -fem_ts_monitor and any other -fem_ts_ monitor run alongside.
#include "gradfric/fem/simulation.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/log_events.hpp"
#include "gradfric/fem/pressed_equilibrium.hpp"
#include "gradfric/fem/run_interruption.hpp"
#include "gradfric/fem/verlet_ts.hpp"
#include "gradfric/physics/friction_laws.hpp"

#include "gradfric/core/input_error.hpp"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <optional>
#include <string>

namespace gradfric::fem {

namespace {

class Experiment {
public:
  Experiment(PlateModel& model, const StepObserver& observer, const CheckpointPlan* checkpoints)
      : model_(model),
        observer_(observer),
        q_(model.params()),
        normal_(q_.plate.pressure * q_.plate.length * q_.plate.length),
        history_(q_.measurement, normal_, model.timeStep()),
        checkpoints_(checkpoints && !checkpoints->settings.path.empty() ? checkpoints : nullptr) {
    r_.dt = model.timeStep();
    r_.stableDt = model.stableTimeStep();
    MPI_Comm_rank(model.comm(), &rank_);
    MPI_Comm_size(model.comm(), &ranks_);
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
    std::optional<RunInterruption> interruption;
    if (checkpoints_) {
      interruption.emplace(model_.comm(), checkpoints_->settings);
      interruption_ = &*interruption;
      lastCheckpoint_ = MPI_Wtime();
    }
    if (checkpoints_ && checkpoints_->resumeFrom)
      resume(ts, X);
    else if (q_.staticPressureStep)
      startFromPressedEquilibrium(X);
    solvePlateTS(ts);
    interruption_ = nullptr;
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
      Experiment& e = of(ts);
      e.afterStep(ts);
      if (e.checkpoints_) e.checkpointIfDue(ts);
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

  // Everything this rank carries from one step to the next, saved or restored in one order.
  void archive(StateArchive& a, TS ts, Vec X) {
    PetscInt step = 0;
    PetscReal t = 0;
    GF_CALL(TSGetStepNumber(ts, &step));
    GF_CALL(TSGetTime(ts, &t));
    a.field("ts.step", step);
    a.field("ts.time", t);
    model_.archive(a);
    history_.archive(a);
    monitor_->archive(a);
    a.field("run.time", r_.time);
    a.field("run.mu", r_.mu);
    a.field("run.normalForce", r_.normalForce);
    a.field("run.forceX", r_.forceX);
    a.field("run.forceY", r_.forceY);
    a.field("run.slideStart", r_.slideStart);
    a.field("run.settledNormalForce", r_.settledNormalForce);
    a.field("run.staticPressureStep", r_.staticPressureStep);
    a.field("run.pressureIterations", r_.pressureIterations);
    a.field("run.peakDampingStart", r_.peakDampingStart);
    a.field("run.steps", r_.steps);
    a.field("run.wallPressure", r_.wallPressure);
    a.field("run.sample", sample_);
    if (checkpoints_->archiveObserver) checkpoints_->archiveObserver(a);
    archiveVec(a, "state", X);
    Vec rhs = verletReusedRhs(ts);
    int haveRhs = rhs != nullptr;
    a.field("ts.haveRhs", haveRhs);
    if (a.restoring()) {
      GF_CALL(TSSetStepNumber(ts, step));
      GF_CALL(TSSetTime(ts, t));
      if (haveRhs) {
        OwnedVec saved;
        GF_CALL(VecDuplicate(X, saved.out()));
        archiveVec(a, "ts.rhs", saved);
        restoreVerletRhs(ts, saved);
      }
    } else if (haveRhs) {
      archiveVec(a, "ts.rhs", rhs);
    }
    a.expectEnd();
  }

  static void archiveVec(StateArchive& a, const char* name, Vec v) {
    PetscInt n = 0;
    GF_CALL(VecGetLocalSize(v, &n));
    std::vector<double> values(static_cast<std::size_t>(n));
    if (!a.restoring()) {  // read only: the vector's state (PETSc's object state) stays as it was
      const PetscScalar* x = nullptr;
      GF_CALL(VecGetArrayRead(v, &x));
      std::copy(x, x + n, values.begin());
      GF_CALL(VecRestoreArrayRead(v, &x));
      a.fixedField(name, values);
      return;
    }
    a.fixedField(name, values);
    PetscScalar* x = nullptr;
    GF_CALL(VecGetArray(v, &x));
    std::copy(values.begin(), values.end(), x);
    GF_CALL(VecRestoreArray(v, &x));
  }

  // -resume: the state of the checkpoint's step; TSSolve continues from it.
  void resume(TS ts, Vec X) {
    const CheckpointHeader& h = *checkpoints_->resumeFrom;
    GF_CALL(TSSetUp(ts));  // gfverlet's data exists (its reused right-hand side is restored into it)
    StateArchive a(readCheckpointBytes(model_.comm(), checkpoints_->settings.path));
    try {
      archive(a, ts, X);
    } catch (const CheckpointMismatch& e) {
      throw InputError("-resume", checkpoints_->settings.path,
                       std::string("a checkpoint of this build and scene (") + e.what() + ")");
    }
    r_.resumedFromStep = h.step;
    if (h.tSliding >= 0)
      GF_CALL(PetscPrintf(model_.comm(), "  resumed from the checkpoint of step %ld (t - t0 = %.6e s) in %s\n", h.step,
                          h.tSliding, checkpoints_->settings.path.c_str()));
    else
      GF_CALL(PetscPrintf(model_.comm(), "  resumed from the checkpoint of step %ld (t = %.6e s, while pressing) in %s\n",
                          h.step, h.time, checkpoints_->settings.path.c_str()));
  }

  // After the post-step: a checkpoint when one is due (rank 0's clock) or a signal came (any rank).
  void checkpointIfDue(TS ts) {
    const CheckpointSettings& s = checkpoints_->settings;
    if (s.testSignal != 0) {  // testing only: the signal a scheduler would send, after a given step
      PetscInt now = 0;
      GF_CALL(TSGetStepNumber(ts, &now));
      if (now == s.testStep) raise(s.testSignal);
    }
    TSConvergedReason reason = TS_CONVERGED_ITERATING;
    GF_CALL(TSGetConvergedReason(ts, &reason));
    const int signal = RunInterruption::pending();
    int flags = (signal == SIGINT ? 2 : 0) | (signal == SIGTERM ? 4 : 0);
    if (rank_ == 0 && s.interval > 0 && MPI_Wtime() - lastCheckpoint_ >= s.interval) flags |= 1;
    if (ranks_ > 1) GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &flags, 1, MPI_INT, MPI_BOR, model_.comm()));
    if (flags == 0) return;
    const bool stopping = reason != TS_CONVERGED_ITERATING;  // the run ends at this step anyway
    if (stopping && !(flags & 6)) return;
    const double start = MPI_Wtime();
    Vec X = nullptr;
    PetscInt step = 0;
    PetscReal t = 0;
    GF_CALL(TSGetSolution(ts, &X));
    GF_CALL(TSGetStepNumber(ts, &step));
    GF_CALL(TSGetTime(ts, &t));
    r_.checkpoints += 1;
    StateArchive a;
    archive(a, ts, X);
    CheckpointHeader h;
    h.step = step;
    h.time = t;
    h.tSliding = model_.phase() == Phase::Sliding ? t - r_.slideStart : -1.0;
    h.ranks = ranks_;
    writeCheckpoint(model_.comm(), s, h, a.bytes());
    r_.checkpointWall += MPI_Wtime() - start;
    lastCheckpoint_ = MPI_Wtime();
    interruption_->kept(step, t, h.tSliding);
    if (!(flags & 6)) return;
    r_.interruptedBy = (flags & 2) ? SIGINT : SIGTERM;
    GF_CALL(TSSetConvergedReason(ts, TS_CONVERGED_USER));
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
    if (recordOnset_) model_.recordOnset(tSliding, r_.dt);
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
  const CheckpointPlan* checkpoints_;  // null: none
  RunInterruption* interruption_ = nullptr;
  double lastCheckpoint_ = 0;  // wall time of the last checkpoint (or of the start)
  int rank_ = 0, ranks_ = 1;
  bool recordOnset_ = isStateLaw(q_.frictionLaw);  // for the interface resolution check
};

}  // namespace

FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer, const CheckpointPlan* checkpoints) {
  Experiment experiment(model, observer, checkpoints);
  return experiment.run();
}

}  // namespace gradfric::fem
