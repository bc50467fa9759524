#pragma once
// The in-memory realisation pool: short, independent tasks (spring-block realisations, or
// (point, realisation) pairs) spread over the ranks of a communicator one rank a task, with
// nothing written to a file. For the study, the design search and the calibration, which need
// every task's numbers on every rank before they decide what to run next. (The campaign runner,
// runner.hpp, is the file-backed, resumable counterpart.)
//
// Each task returns a record of `width` doubles. The records are gathered by their task index,
// copied bit for bit (no arithmetic), so every rank ends with the same table whatever the number
// of ranks or the schedule. A task that throws ends the pool on every rank with the same
// CollectiveError: the failure of the first failing task in hand-out order, which every rank
// count runs (a rank stops taking tasks after its first failure only), so the message names the
// same task on 1, 2 or 3 ranks. Never a hang: ranks that finish early wait quietly for the
// others (core/quiet_wait.hpp) before the one agreement.
#include "gradfric/campaign/scheduler.hpp"

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace gradfric::campaign {

struct PoolPlan {
  long tasks = 0;  // task indices 0 .. tasks - 1
  int width = 1;   // doubles in each task's record
  Schedule schedule = Schedule::Dynamic;
  // The order the tasks are handed out in, a permutation of 0 .. tasks - 1 (empty: index order).
  // Costly tasks first lets the ranks finish together; the results stay in task order.
  std::vector<long> handOutOrder;
  // The message of task `task` that threw `what` on `rank` (empty: "task <k> failed on rank <r>: <what>").
  std::function<std::string(long task, int rank, const std::string& what)> failure;
};

// What one task computes: its record of plan.width doubles. Runs on one rank, without
// communication on the pool's communicator.
using PoolTask = std::function<std::vector<double>(long task)>;

// Collective over comm: runs every task once and returns their records on every rank, task k's
// at [k width, (k + 1) width). Throws CollectiveError on every rank if any task failed.
std::vector<double> runRealisationPool(MPI_Comm comm, const PoolPlan& plan, const PoolTask& task);

}  // namespace gradfric::campaign
