// The in-memory realisation pool (include/gradfric/campaign/realisation_pool.hpp).
#include "gradfric/campaign/realisation_pool.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/gather.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/quiet_wait.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace gradfric::campaign {

namespace {

// Every rank holds the same plan, so a malformed one is refused on every rank alike.
void checkPlan(const PoolPlan& plan) {
  if (plan.tasks < 0 || plan.width < 1) throw std::logic_error("realisation pool: negative task count or empty record");
  if (plan.tasks > INT_MAX / plan.width) throw std::logic_error("realisation pool: more doubles than one MPI count holds");
  if (plan.handOutOrder.empty()) return;
  std::vector<char> seen(static_cast<std::size_t>(plan.tasks), 0);
  bool permutation = static_cast<long>(plan.handOutOrder.size()) == plan.tasks;
  for (long k : plan.handOutOrder) {
    if (!permutation) break;
    permutation = k >= 0 && k < plan.tasks && !seen[k];
    if (permutation) seen[k] = 1;
  }
  if (!permutation) throw std::logic_error("realisation pool: the hand-out order is not a permutation of the tasks");
}

std::string failureMessage(const PoolPlan& plan, long task, int rank, const std::string& what) {
  if (plan.failure) return plan.failure(task, rank, what);
  return "task " + std::to_string(task) + " failed on rank " + std::to_string(rank) + ": " + what;
}

// What this rank ran: the task indices in the order it ran them, their records one after another,
// and its first failure (hand-out position `failedAt`, plan.tasks when none).
struct LocalRuns {
  std::vector<long> tasks;
  std::vector<double> records;
  long failedAt = 0;
  std::string failure;
};

LocalRuns runLocally(MPI_Comm comm, int rank, const PoolPlan& plan, const PoolTask& task) {
  LocalRuns local;
  local.failedAt = plan.tasks;
  TaskCounter counter(comm, plan.schedule);
  for (long position = counter.next(); position < plan.tasks; position = counter.next()) {
    const long k = plan.handOutOrder.empty() ? position : plan.handOutOrder[position];
    try {
      const std::vector<double> record = task(k);
      if (static_cast<long>(record.size()) != plan.width)
        throw std::logic_error("a record of " + std::to_string(record.size()) + " values where the pool expects " +
                               std::to_string(plan.width));
      local.tasks.push_back(k);
      local.records.insert(local.records.end(), record.begin(), record.end());
    } catch (const std::exception& e) {
      local.failure = failureMessage(plan, k, rank, e.what());
    } catch (...) {
      local.failure = failureMessage(plan, k, rank, "an exception of unknown type");
    }
    // Stop at the first failure: every position before it is still run by some rank, so the first
    // failing position over all ranks is the same on any number of ranks.
    if (!local.failure.empty()) {
      local.failedAt = position;
      break;
    }
  }
  // The tail: wait without spinning, before the counter's window is freed (a collective that polls).
  waitForRanks(comm);
  return local;
}

}  // namespace

std::vector<double> runRealisationPool(MPI_Comm comm, const PoolPlan& plan, const PoolTask& task) {
  checkPlan(plan);
  if (plan.tasks == 0) return {};
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  const LocalRuns local = runLocally(comm, rank, plan, task);

  long firstFailure = local.failedAt;
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &firstFailure, 1, MPI_LONG, MPI_MIN, comm));
  if (firstFailure < plan.tasks) agreeOnError(comm, local.failedAt == firstFailure ? local.failure : std::string());

  // Each record is copied, never summed: the bits cannot depend on who ran it.
  const std::vector<long> ran = gatherOnAll(comm, local.tasks);
  const std::vector<double> records = gatherOnAll(comm, local.records);
  const std::size_t width = static_cast<std::size_t>(plan.width);
  std::vector<double> byTask(static_cast<std::size_t>(plan.tasks) * width);
  std::vector<char> filled(static_cast<std::size_t>(plan.tasks), 0);
  for (std::size_t i = 0; i < ran.size(); ++i) {
    const auto k = static_cast<std::size_t>(ran[i]);
    if (filled[k]) throw std::logic_error("realisation pool: task " + std::to_string(k) + " ran twice");
    filled[k] = 1;
    std::copy_n(records.begin() + static_cast<std::ptrdiff_t>(i * width), width,
                byTask.begin() + static_cast<std::ptrdiff_t>(k * width));
  }
  if (ran.size() != static_cast<std::size_t>(plan.tasks))
    throw std::logic_error("realisation pool: " + std::to_string(ran.size()) + " of " + std::to_string(plan.tasks) +
                           " tasks ran");
  return byTask;
}

}  // namespace gradfric::campaign
