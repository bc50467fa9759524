#include "gradfric/fem/pressed_equilibrium.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/petsc_handle.hpp"
#include "gradfric/core/reproducible_sum.hpp"
#include "gradfric/fem/state_view.hpp"

#include <petscksp.h>
#include <petscversion.h>
// The exact dot and norm replace entries of a vector's private table of operations (PETSc 3.18 has
// no public VecSetOperation for them), whose layout PETSc may change between releases.
#if PETSC_VERSION_LT(3, 18, 0)
#error "the static solve's exact dot and norm need PETSc 3.18 or later (the private Vec operations they set)"
#elif PETSC_VERSION_GE(3, 19, 0)
#warning "the static solve's exact dot and norm were checked with PETSc 3.18: check the private Vec operations against this release"
#endif
#include <petsc/private/vecimpl.h>  // the place of dot and norm in the table of operations

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gradfric::fem {

namespace {

using OwnedKSP = PetscHandle<KSP, KSPDestroy>;

// y = (K + P) x on the displacement DM: K from the specialised kernel (f = -K x), P the diagonal
// penalty springs of the bottom nodes.
struct PressedOperator {
  ElasticOperator* elastic = nullptr;
  Vec penalty = nullptr, stiffnessDiagonal = nullptr;
};

PetscErrorCode multiply(Mat A, Vec x, Vec y) {
  PressedOperator* op = nullptr;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &op));
  try {
    op->elastic->forceSpecialised(x, y);  // y = -K x
  } catch (...) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "static pressure step: the elastic force failed");
  }
  PetscInt n = 0;
  PetscCall(VecGetLocalSize(y, &n));
  const PetscScalar *xx = nullptr, *p = nullptr;
  PetscScalar* yy = nullptr;
  PetscCall(VecGetArrayRead(x, &xx));
  PetscCall(VecGetArrayRead(op->penalty, &p));
  PetscCall(VecGetArray(y, &yy));
  for (PetscInt i = 0; i < n; ++i) yy[i] = p[i] * xx[i] - yy[i];
  PetscCall(VecRestoreArray(y, &yy));
  PetscCall(VecRestoreArrayRead(op->penalty, &p));
  PetscCall(VecRestoreArrayRead(x, &xx));
  PetscFunctionReturn(0);
}

PetscErrorCode diagonal(Mat A, Vec d) {
  PressedOperator* op = nullptr;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &op));
  PetscCall(VecCopy(op->stiffnessDiagonal, d));
  PetscFunctionReturn(0);
}

// CG's dot products and norms as exact sums over ranks: the iterates, and so the pressed state,
// then have the same bits on any number of ranks (PETSc's own reductions add rank-partial sums).
// Set on the solution and the load; KSP's work vectors inherit them through VecDuplicate.
PetscErrorCode exactDot(Vec x, Vec y, PetscScalar* value) {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  const PetscScalar *a = nullptr, *b = nullptr;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(VecGetArrayRead(y, &b));
  ExactSum sum;
  for (PetscInt i = 0; i < n; ++i) sum.add(a[i] * b[i]);
  PetscCall(VecRestoreArrayRead(y, &b));
  PetscCall(VecRestoreArrayRead(x, &a));
  try {
    *value = sumOverRanks(PetscObjectComm(reinterpret_cast<PetscObject>(x)), sum);
  } catch (...) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "static pressure step: the exact dot product failed");
  }
  PetscFunctionReturn(0);
}

PetscErrorCode exactNorm(Vec x, NormType type, PetscReal* value) {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  const PetscScalar* a = nullptr;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  ExactSum sums[2];  // sum |x_i| and sum x_i^2
  double largest = 0;
  for (PetscInt i = 0; i < n; ++i) {
    sums[0].add(std::fabs(a[i]));
    sums[1].add(a[i] * a[i]);
    largest = std::max(largest, std::fabs(a[i]));
  }
  PetscCall(VecRestoreArrayRead(x, &a));
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(x));
  try {
    allreduceExact(comm, sums, 2);
  } catch (...) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "static pressure step: the exact norm failed");
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, comm));
  if (type == NORM_1) value[0] = sums[0].value();
  else if (type == NORM_2 || type == NORM_FROBENIUS) value[0] = std::sqrt(sums[1].value());
  else if (type == NORM_INFINITY) value[0] = largest;
  else {  // NORM_1_AND_2
    value[0] = sums[0].value();
    value[1] = std::sqrt(sums[1].value());
  }
  PetscFunctionReturn(0);
}

// PETSc 3.18 names no VecOperation for dot and norm: the slot is the member's place in the
// (private) table of operations, taken from the table itself so that it follows the version.
VecOperation operationOf(std::size_t memberOffset) {
  return static_cast<VecOperation>(memberOffset / sizeof(PetscErrorCode(*)(void)));
}

using Op = void (*)(void);
Op plainDuplicate = nullptr;  // the vectors' own VecDuplicate

void setExactReductions(Vec v);

// KSP's work vectors are duplicates of the solution: they get the exact reductions too.
PetscErrorCode duplicateWithExactReductions(Vec v, Vec* copy) {
  PetscFunctionBeginUser;
  PetscCall(reinterpret_cast<PetscErrorCode (*)(Vec, Vec*)>(plainDuplicate)(v, copy));
  try {
    setExactReductions(*copy);
  } catch (...) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "static pressure step: setting exact reductions failed");
  }
  PetscFunctionReturn(0);
}

void setExactReductions(Vec v) {
  GF_CALL(VecSetOperation(v, operationOf(offsetof(_VecOps, dot)), reinterpret_cast<Op>(exactDot)));
  GF_CALL(VecSetOperation(v, operationOf(offsetof(_VecOps, tdot)), reinterpret_cast<Op>(exactDot)));
  GF_CALL(VecSetOperation(v, operationOf(offsetof(_VecOps, norm)), reinterpret_cast<Op>(exactNorm)));
  GF_CALL(VecSetOperation(v, VECOP_DUPLICATE, reinterpret_cast<Op>(duplicateWithExactReductions)));
}

void useExactReductions(Vec v) {
  const Op own = reinterpret_cast<Op>(v->ops->duplicate);  // 3.18 has no VecGetOperation
  if (own != reinterpret_cast<Op>(duplicateWithExactReductions)) plainDuplicate = own;
  setExactReductions(v);
}

}  // namespace

PressedEquilibrium solvePressedEquilibrium(PlateModel& model, Vec X, double relativeTolerance) {
  PressedEquilibrium out;
  const FemParameters& q = model.params();
  DM dmU = model.elastic().displacementDM();
  OwnedVec u, load, penalty, diag;
  GF_CALL(DMCreateGlobalVector(dmU, u.out()));
  GF_CALL(VecDuplicate(u, load.out()));
  GF_CALL(VecDuplicate(u, penalty.out()));
  GF_CALL(VecDuplicate(u, diag.out()));
  useExactReductions(u);
  useExactReductions(load);
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(u, &n));
  {  // the load: the layers' dead loads at their full value (the top pressure, the weight)
    OwnedVec stateForce;
    GF_CALL(VecDuplicate(X, stateForce.out()));
    GF_CALL(VecZeroEntries(stateForce));
    for (const Layer* layer : model.layers()) layer->addDeadLoad(stateForce);
    const ReadState f(stateForce);
    PetscScalar* b = nullptr;
    GF_CALL(VecGetArray(load, &b));
    for (PetscInt k = 0; k < n / 3; ++k)
      for (int d = 0; d < 3; ++d) b[3 * k + d] = f.force(k)[d];
    GF_CALL(VecRestoreArray(load, &b));
  }
  {  // the contact springs at rest: k A per bottom node, tangential and normal
    GF_CALL(VecZeroEntries(penalty));
    PetscScalar* p = nullptr;
    GF_CALL(VecGetArray(penalty, &p));
    for (const ContactBoundary::Node& node : model.contact().nodes()) {
      p[3 * node.block + 0] = p[3 * node.block + 1] = q.kt * node.area;
      p[3 * node.block + 2] = q.kn * node.area;
    }
    GF_CALL(VecRestoreArray(penalty, &p));
  }
  GF_CALL(VecCopy(penalty, diag));
  model.elastic().addStiffnessDiagonal(diag);
  PressedOperator op{&model.elastic(), penalty, diag};
  OwnedMat A;
  GF_CALL(MatCreateShell(model.comm(), n, n, PETSC_DETERMINE, PETSC_DETERMINE, &op, A.out()));
  GF_CALL(MatShellSetOperation(A, MATOP_MULT, reinterpret_cast<void (*)(void)>(multiply)));
  GF_CALL(MatShellSetOperation(A, MATOP_GET_DIAGONAL, reinterpret_cast<void (*)(void)>(diagonal)));
  GF_CALL(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
  OwnedKSP ksp;
  GF_CALL(KSPCreate(model.comm(), ksp.out()));
  GF_CALL(KSPSetOperators(ksp, A, A));
  GF_CALL(KSPSetType(ksp, KSPCG));
  PC pc = nullptr;
  GF_CALL(KSPGetPC(ksp, &pc));
  GF_CALL(PCSetType(pc, PCJACOBI));
  GF_CALL(KSPSetTolerances(ksp, relativeTolerance, 0.0, PETSC_DEFAULT, 100000));
  GF_CALL(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  GF_CALL(VecZeroEntries(u));
  GF_CALL(KSPSolve(ksp, load, u));
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  GF_CALL(KSPGetConvergedReason(ksp, &reason));
  PetscInt iterations = 0;
  GF_CALL(KSPGetIterationNumber(ksp, &iterations));
  out.iterations = static_cast<int>(iterations);
  PetscReal rnorm = 0, bnorm = 0;
  GF_CALL(KSPGetResidualNorm(ksp, &rnorm));
  GF_CALL(VecNorm(load, NORM_2, &bnorm));
  out.residual = bnorm > 0 ? rnorm / bnorm : 0.0;
  if (reason < 0) {
    out.why = std::string("CG did not converge (") + KSPConvergedReasons[reason] + ")";
    return out;
  }
  {  // X = [u, 0]
    const PetscScalar* uu = nullptr;
    GF_CALL(VecGetArrayRead(u, &uu));
    {
      const WriteState x(X);
      for (PetscInt k = 0; k < n / 3; ++k)
        for (int d = 0; d < 3; ++d) {
          x.displacement(k)[d] = uu[3 * k + d];
          x.velocity(k)[d] = 0.0;
        }
    }
    GF_CALL(VecRestoreArrayRead(u, &uu));
  }
  // The contact law on the solution (anchors at rest, as the springs above): stick everywhere?
  OwnedVec F;
  GF_CALL(VecDuplicate(X, F.out()));
  model.rhs(q.rampTime, X, F);  // step 1 at full pressure
  const ContactTotals totals = model.contactTotals();
  out.normalForce = totals.fn;
  out.slipping = totals.slip;
  out.open = totals.open;
  if (totals.slip > 0 || totals.open > 0) {
    out.why = std::to_string(totals.slip) + " bottom node(s) would slip and " + std::to_string(totals.open) +
              " lose contact under the static load";
    GF_CALL(VecZeroEntries(X));
    return out;
  }
  model.postStep();
  out.holds = true;
  return out;
}

}  // namespace gradfric::fem
