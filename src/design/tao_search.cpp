// The several-parameter design search with PETSc TAO (include/gradfric/design/tao_search.hpp).
#include "gradfric/design/tao_search.hpp"

#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/petsc_handle.hpp"

#include <petsctao.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

namespace gradfric::design {

namespace {

using OwnedTao = PetscHandle<Tao, TaoDestroy>;

struct Context {
  MPI_Comm comm;
  Evaluator* evaluator;
  const Problem* problem;
  SearchLog* log;
  std::optional<Evaluation> found;
  std::exception_ptr failure;  // an exception must not cross PETSc's C frames: kept, rethrown after
};

// The scaled point u (owned by rank 0) on every rank.
std::vector<double> scaledPoint(const Context& c, Vec u) {
  std::vector<double> values(c.problem->dimension(), 0.0);
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(c.comm, &rank));
  if (rank == 0) {
    const PetscScalar* a = nullptr;
    GF_CALL(VecGetArrayRead(u, &a));
    std::copy(a, a + values.size(), values.begin());
    GF_CALL(VecRestoreArrayRead(u, &a));
  }
  GF_CALL_MPI(MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, c.comm));
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
  const Evaluation& e = c.log->add(c.evaluator->evaluate(x, c.problem->tolerance, "tao"));
  if (!c.found && c.log->meets(e)) c.found = e;
  const double r = (e.value - c.problem->target) / c.problem->tolerance;
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

// A vector of `d` entries, all on rank 0 (the same layout on any number of ranks: the same sums).
OwnedVec rankZeroVector(MPI_Comm comm, int d, double value) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  OwnedVec v;
  GF_CALL(VecCreateMPI(comm, rank == 0 ? d : 0, d, v.out()));
  GF_CALL(VecSet(v, value));
  return v;
}

}  // namespace

SearchResult searchWithTao(MPI_Comm comm, Evaluator& evaluator, const Problem& problem, SearchLog& log) {
  const int d = problem.dimension();
  Context c{comm, &evaluator, &problem, &log, std::nullopt, nullptr};
  OwnedVec u = rankZeroVector(comm, d, 0.5), lower = rankZeroVector(comm, d, 0.0), upper = rankZeroVector(comm, d, 1.0);
  OwnedVec residuals = rankZeroVector(comm, 1, 0.0);
  OwnedTao tao;
  GF_CALL(TaoCreate(comm, tao.out()));
  GF_CALL(TaoSetType(tao, TAONM));
  GF_CALL(TaoSetSolution(tao, u));
  GF_CALL(TaoSetObjective(tao, objective, &c));
  GF_CALL(TaoSetResidualRoutine(tao, residuals, residualVector, &c));
  GF_CALL(TaoSetVariableBounds(tao, lower, upper));
  GF_CALL(TaoSetTolerances(tao, 0.25, 0.0, 0.0));
  GF_CALL(TaoSetMaximumFunctionEvaluations(tao, problem.maxEvaluations));
  GF_CALL(TaoSetMaximumIterations(tao, problem.maxEvaluations));
  GF_CALL(TaoSetConvergenceTest(tao, convergence, &c));
  GF_CALL(TaoSetFromOptions(tao));  // -tao_type pounders, -tao_monitor, ...
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
