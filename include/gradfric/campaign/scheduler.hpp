#pragma once
// Hands out task indices 0, 1, 2, ... to the ranks of a communicator.
//   dynamic: a shared counter on rank 0 of comm, advanced with MPI_Fetch_and_op (passive-target
//            one-sided, no dispatcher rank: rank 0 computes too). A rank that finishes a task
//            takes the next index, so ranks stay busy when tasks differ in cost.
//   static:  rank k takes k, k + size, k + 2 size, ... (no one-sided communication; a fallback
//            for MPI installations whose passive-target progress is poor).
// Also counts finished tasks over all ranks (for the progress line's estimate).
#include <mpi.h>

namespace gradfric::campaign {

enum class Schedule { Dynamic, Static };

class TaskCounter {
public:
  // Collective over comm.
  TaskCounter(MPI_Comm comm, Schedule schedule);
  ~TaskCounter();  // collective (frees the window)
  TaskCounter(const TaskCounter&) = delete;
  TaskCounter& operator=(const TaskCounter&) = delete;

  // The next task index for this rank (may be >= the number of tasks: then stop).
  long next();
  // Records one finished task; returns the number finished over all ranks so far (dynamic) or
  // an estimate (static: this rank's count times the number of ranks).
  long finishOne();
  // The number finished over all ranks so far, without changing it (static: an estimate).
  long finishedSoFar();

private:
  long fetchAdd(int slot, bool add = true);
  MPI_Comm comm_;
  Schedule schedule_;
  int rank_ = 0;
  int size_ = 1;
  long localTaken_ = 0;
  long localFinished_ = 0;
  MPI_Win window_ = MPI_WIN_NULL;
  long* counters_ = nullptr;
};

}  // namespace gradfric::campaign
