#include "gradfric/fem/simulation.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/fem/verlet_ts.hpp"

#include <cmath>
#include <exception>

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

FemRunResult runPlateExperiment(PlateModel& model, const StepObserver& observer) {
  const FemParameters& q = model.params();
  FemRunResult r;
  r.dt = model.timeStep();
  r.stableDt = model.stableTimeStep();
  OwnedVec X(model.createState());
  OwnedTS ts(createPlateTS(model, X));
  const double normal = q.p * q.L * q.L;

  // Step 1: pressure ramp and hold.
  model.setPhase(Phase::Pressure);
  double t0 = MPI_Wtime();
  const double tSettle = q.rampTime + q.settleTime;
  PetscReal t = 0;
  while (t < tSettle - 0.5 * r.dt) {
    GF_CALL(TSStep(ts));
    model.commitContact();
    GF_CALL(TSGetTime(ts, &t));
    ++r.steps;
  }
  r.settledNormalForce = model.contactTotals().fn / normal;
  if (q.verbose)
    GF_CALL(PetscPrintf(model.comm(), "  step 1 done: t = %.4e s, %ld steps, normal force %.6f p L^2\n", t, r.steps,
                        r.settledNormalForce));
  r.wallPressure = MPI_Wtime() - t0;

  // Step 2: the top slides at v.
  Vec state = nullptr;
  GF_CALL(TSGetSolution(ts, &state));
  model.startSliding(state);
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
