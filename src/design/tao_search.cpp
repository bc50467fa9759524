// The several-parameter design search with PETSc TAO (include/gradfric/design/tao_search.hpp).
#include "gradfric/design/tao_search.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/petsc_handle.hpp"

#include <petsctao.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <string>

namespace gradfric::design {

namespace {

using OwnedTao = PetscHandle<Tao, TaoDestroy>;

struct Context {
  MPI_Comm comm;
  DesignModel* evaluator;
  const Problem* problem;
  SearchLog* log;
  std::optional<Evaluation> found;
  int count = 0;  // realisations of every objective evaluation (set by the first)
  std::exception_ptr failure;  // an exception must not cross PETSc's C frames: kept, rethrown after
};

// The scaled point u (every rank holds the same: TAO runs redundantly).
std::vector<double> scaledPoint(const Context& c, Vec u) {
  std::vector<double> values(c.problem->dimension(), 0.0);
  const PetscScalar* a = nullptr;
  GF_CALL(VecGetArrayRead(u, &a));
  std::copy(a, a + values.size(), values.begin());
  GF_CALL(VecRestoreArrayRead(u, &a));
  return values;
}

// The residual (value - target) / tolerance at u, with the distance outside [0, 1] as a penalty.
double residual(Context& c, Vec u) {
  const std::vector<double> scaled = scaledPoint(c, u);
  std::vector<double> x(scaled.size());
  double outside = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double s = std::clamp(scaled[i], 0.0, 1.0);
    outside += (scaled[i] - s) * (scaled[i] - s);
    const FreeParameter& f = c.problem->free[i];
    x[i] = f.lower + s * (f.upper - f.lower);
  }
  // The first evaluation runs to the tolerance and fixes the count of the others: on common
  // streams and one count the objective is smooth in x. One whose CI holds the target is refined.
  const Evaluation& e = c.log->add(c.evaluator->evaluate(x, c.count ? c.problem->coarse : c.problem->tolerance, "tao", 0, c.count));
  if (!c.count) c.count = e.realisations;
  const double r = (e.value - c.problem->target) / c.problem->tolerance;
  if (!c.found && e.side(c.problem->target) == 0) {
    const Evaluation& refined = c.log->meets(e) ? e : c.log->add(c.evaluator->evaluate(x, c.problem->tolerance, "refine"));
    if (c.log->meets(refined)) c.found = refined;
  }
  return std::copysign(std::sqrt(r * r + 100.0 * outside), r);
}

PetscErrorCode objective(Tao, Vec u, PetscReal* f, void* context) {
  auto& c = *static_cast<Context*>(context);
  try {
    const double r = residual(c, u);
    *f = r * r;
    return 0;
  } catch (...) {
    c.failure = std::current_exception();
    return PETSC_ERR_USER;
  }
}

PetscErrorCode residualVector(Tao, Vec u, Vec out, void* context) {
  auto& c = *static_cast<Context*>(context);
  try {
    const double r = residual(c, u);
    GF_CALL(VecSet(out, r));
    return 0;
  } catch (...) {
    c.failure = std::current_exception();
    return PETSC_ERR_USER;
  }
}

PetscErrorCode convergence(Tao tao, void* context) {
  auto& c = *static_cast<Context*>(context);
  if (c.found) return TaoSetConvergedReason(tao, TAO_CONVERGED_USER);
  return TaoDefaultConvergenceTest(tao, nullptr);
}

OwnedVec sequentialVector(int d, double value) {
  OwnedVec v;
  GF_CALL(VecCreateSeq(PETSC_COMM_SELF, d, v.out()));
  GF_CALL(VecSet(v, value));
  return v;
}

}  // namespace

void readDesignTaoOptions() {
  refuseUnprefixedOptions("tao_", kDesignTaoPrefix, "the design's TAO reads its options with the prefix design_");
  const std::string typeOption = std::string("-") + kDesignTaoPrefix + "tao_type";
  char type[256] = "";
  PetscBool typeGiven = PETSC_FALSE;
  GF_CALL(PetscOptionsGetString(nullptr, nullptr, typeOption.c_str(), type, sizeof type, &typeGiven));
  OwnedTao tao;
  GF_CALL(TaoCreate(PETSC_COMM_SELF, tao.out()));
  GF_CALL(TaoSetOptionsPrefix(tao, kDesignTaoPrefix));
  GF_CALL(TaoSetType(tao, TAONM));
  const PetscErrorCode code = TaoSetFromOptions(tao);
  if (code == PETSC_ERR_ARG_UNKNOWN_TYPE && typeGiven)
    throw InputError(typeOption, type, "nm (the default), pounders or another PETSc TAO type");
  GF_CALL(code);
}

SearchResult searchWithTao(MPI_Comm comm, DesignModel& evaluator, const Problem& problem, SearchLog& log) {
  const int d = problem.dimension();
  Context c{comm, &evaluator, &problem, &log, std::nullopt, 0, nullptr};
  OwnedVec u = sequentialVector(d, 0.5), lower = sequentialVector(d, 0.0), upper = sequentialVector(d, 1.0);
  OwnedVec residuals = sequentialVector(1, 0.0);
  // TAO on every rank alike (PETSC_COMM_SELF: a handful of parameters, and pounders is serial):
  // the objective values are the same on every rank, so are TAO's steps; each objective
  // evaluation is an ensemble collective over comm.
  OwnedTao tao;
  GF_CALL(TaoCreate(PETSC_COMM_SELF, tao.out()));
  GF_CALL(TaoSetType(tao, TAONM));
  GF_CALL(TaoSetSolution(tao, u));
  GF_CALL(TaoSetObjective(tao, objective, &c));
  GF_CALL(TaoSetResidualRoutine(tao, residuals, residualVector, &c));
  GF_CALL(TaoSetVariableBounds(tao, lower, upper));
  GF_CALL(TaoSetTolerances(tao, 0.25, 0.0, 0.0));
  GF_CALL(TaoSetMaximumFunctionEvaluations(tao, problem.maxEvaluations));
  GF_CALL(TaoSetMaximumIterations(tao, problem.maxEvaluations));
  GF_CALL(TaoSetConvergenceTest(tao, convergence, &c));
  GF_CALL(TaoSetOptionsPrefix(tao, kDesignTaoPrefix));
  GF_CALL(TaoSetFromOptions(tao));  // -design_tao_type pounders, -design_tao_monitor, ...
  TaoType type = nullptr;
  GF_CALL(TaoGetType(tao, &type));
  const std::string method = std::string("tao ") + type;
  const PetscErrorCode status = TaoSolve(tao);
  if (c.failure) std::rethrow_exception(c.failure);
  GF_CALL(status);
  if (c.found) return {Status::Found, *c.found, method, "the target lies in the CI of the design"};
  TaoConvergedReason reason;
  GF_CALL(TaoGetConvergedReason(tao, &reason));
  const Evaluation closest = log.closest();
  const Evaluation& e = log.add(evaluator.evaluate(closest.x, problem.tolerance, "closest"));
  if (log.meets(e)) return {Status::Found, e, method, "the closest evaluation, refined, holds the target in its CI"};
  const std::string why = std::string("TAO stopped: ") + TaoConvergedReasons[reason];
  if (reason > 0) return {Status::Unreachable, e, method, why + "; the design is the closest attainable value"};
  return {Status::NotConverged, e, method, why + "; the design is the closest evaluation"};
}

}  // namespace gradfric::design
