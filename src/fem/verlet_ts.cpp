#include "gradfric/fem/verlet_ts.hpp"

#include "gradfric/core/petsc_call.hpp"

#include <petscversion.h>
// A TS implementation sees PETSc's private TS structure (data, vec_sol, ptime, time_step,
// steprestart, default_adapt_type, ops->setup/step/reset/destroy), whose layout PETSc may change
// between releases: this file is checked with PETSc 3.18 (Debian's, the project's stack).
#if PETSC_VERSION_LT(3, 18, 0)
#error "gfverlet needs PETSc 3.18 or later (the private TS members it sets)"
#elif PETSC_VERSION_GE(3, 19, 0)
#warning "gfverlet was checked with PETSc 3.18: check the private TS members it sets against this release (tests fem_*)"
#endif
#include <petsc/private/tsimpl.h>

#include <cstring>
#include <stdexcept>

// PETSc callbacks of the project's TS type.
namespace {

struct VerletData {
  Vec rhs = nullptr;  // [v ; a] at the current solution
  PetscBool haveRhs = PETSC_FALSE;
  PetscBool restored = PETSC_FALSE;  // a checkpoint's rhs: reused even though TSSolve restarts the step
};

PetscErrorCode TSSetUp_GFVerlet(TS ts) {
  auto* d = static_cast<VerletData*>(ts->data);
  PetscFunctionBeginUser;
  if (!d->rhs) PetscCall(VecDuplicate(ts->vec_sol, &d->rhs));
  d->haveRhs = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode TSReset_GFVerlet(TS ts) {
  auto* d = static_cast<VerletData*>(ts->data);
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&d->rhs));
  d->haveRhs = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode TSDestroy_GFVerlet(TS ts) {
  PetscFunctionBeginUser;
  PetscCall(TSReset_GFVerlet(ts));
  PetscCall(PetscFree(ts->data));
  PetscFunctionReturn(0);
}

PetscErrorCode halfKick(Vec X, Vec F, PetscReal h, PetscInt bs) {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  PetscCall(VecGetLocalSize(X, &n));
  PetscScalar* x = nullptr;
  const PetscScalar* f = nullptr;
  PetscCall(VecGetArray(X, &x));
  PetscCall(VecGetArrayRead(F, &f));
  const PetscInt k = bs / 2;
  for (PetscInt b = 0; b < n; b += bs)
    for (PetscInt c = k; c < bs; ++c) x[b + c] += h * f[b + c];
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscFunctionReturn(0);
}

// The first half kick and the drift in one pass over the state (the same operations per value as
// a half kick followed by a drift: v += h f, then x += dt v with the kicked v).
PetscErrorCode halfKickAndDrift(Vec X, Vec F, PetscReal h, PetscReal dt, PetscInt bs) {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  PetscCall(VecGetLocalSize(X, &n));
  PetscScalar* x = nullptr;
  const PetscScalar* f = nullptr;
  PetscCall(VecGetArray(X, &x));
  PetscCall(VecGetArrayRead(F, &f));
  const PetscInt k = bs / 2;
  for (PetscInt b = 0; b < n; b += bs)
    for (PetscInt c = 0; c < k; ++c) {
      x[b + k + c] += h * f[b + k + c];
      x[b + c] += dt * x[b + k + c];
    }
  PetscCall(VecRestoreArray(X, &x));
  PetscCall(VecRestoreArrayRead(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode TSStep_GFVerlet(TS ts) {
  auto* d = static_cast<VerletData*>(ts->data);
  PetscFunctionBeginUser;
  Vec X = ts->vec_sol;
  const PetscReal t = ts->ptime, dt = ts->time_step;
  PetscInt bs = 1;
  PetscCall(VecGetBlockSize(X, &bs));
  PetscCheck(bs >= 2 && bs % 2 == 0, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONG,
             "gfverlet needs a state of block size 2k [positions, velocities], got %" PetscInt_FMT, bs);
  if (!d->rhs) PetscCall(VecDuplicate(X, &d->rhs));
  if (d->restored) {
    d->restored = PETSC_FALSE;
  } else if (!d->haveRhs || ts->steprestart) {  // TSRestartStep: the solution or the forces changed outside
    PetscCall(TSComputeRHSFunction(ts, t, X, d->rhs));
    d->haveRhs = PETSC_TRUE;
  }
  PetscCall(TSPreStage(ts, t));
  PetscCall(halfKickAndDrift(X, d->rhs, 0.5 * dt, dt, bs));
  PetscCall(TSComputeRHSFunction(ts, t + dt, X, d->rhs));
  PetscCall(halfKick(X, d->rhs, 0.5 * dt, bs));
  PetscCall(TSPostStage(ts, t + dt, 0, &X));
  ts->ptime += dt;
  PetscFunctionReturn(0);
}

PetscErrorCode TSCreate_GFVerlet(TS ts) {
  PetscFunctionBeginUser;
  VerletData* d = nullptr;
  PetscCall(PetscNew(&d));
  ts->data = d;
  ts->ops->setup = TSSetUp_GFVerlet;
  ts->ops->step = TSStep_GFVerlet;
  ts->ops->reset = TSReset_GFVerlet;
  ts->ops->destroy = TSDestroy_GFVerlet;
  ts->default_adapt_type = TSADAPTNONE;
  PetscFunctionReturn(0);
}

}  // namespace

namespace gradfric::fem {

Vec verletReusedRhs(TS ts) {
  TSType type = nullptr;
  GF_CALL(TSGetType(ts, &type));
  if (!type || std::strcmp(type, TSGFVERLET) != 0) return nullptr;
  auto* d = static_cast<VerletData*>(ts->data);
  return d && d->haveRhs ? d->rhs : nullptr;
}

void restoreVerletRhs(TS ts, Vec rhs) {
  TSType type = nullptr;
  GF_CALL(TSGetType(ts, &type));
  if (!type || std::strcmp(type, TSGFVERLET) != 0) throw std::logic_error("restoreVerletRhs: not a gfverlet TS");
  GF_CALL(TSSetUp(ts));
  auto* d = static_cast<VerletData*>(ts->data);
  if (!d->rhs) GF_CALL(VecDuplicate(ts->vec_sol, &d->rhs));
  GF_CALL(VecCopy(rhs, d->rhs));
  d->haveRhs = PETSC_TRUE;
  d->restored = PETSC_TRUE;
}

void registerVerletTS() {
  static bool done = false;
  if (done) return;
  GF_CALL(TSRegister(TSGFVERLET, TSCreate_GFVerlet));
  done = true;
}

}  // namespace gradfric::fem
