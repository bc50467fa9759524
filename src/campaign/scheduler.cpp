#include "gradfric/campaign/scheduler.hpp"

#include "gradfric/core/petsc_call.hpp"

namespace gradfric::campaign {

TaskCounter::TaskCounter(MPI_Comm comm, Schedule schedule) : comm_(comm), schedule_(schedule) {
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank_));
  GF_CALL_MPI(MPI_Comm_size(comm, &size_));
  if (schedule_ != Schedule::Dynamic) return;
  const MPI_Aint bytes = rank_ == 0 ? 2 * sizeof(long) : 0;
  GF_CALL_MPI(MPI_Win_allocate(bytes, sizeof(long), MPI_INFO_NULL, comm, &counters_, &window_));
  GF_CALL_MPI(MPI_Win_lock_all(0, window_));
  if (rank_ == 0) {
    counters_[0] = 0;  // next task index
    counters_[1] = 0;  // tasks finished
    GF_CALL_MPI(MPI_Win_sync(window_));
  }
  GF_CALL_MPI(MPI_Barrier(comm));
}

TaskCounter::~TaskCounter() {
  if (window_ == MPI_WIN_NULL) return;
  MPI_Win_unlock_all(window_);
  MPI_Win_free(&window_);
}

long TaskCounter::fetchAdd(int slot, bool add) {
  const long one = 1;
  long previous = 0;
  GF_CALL_MPI(MPI_Fetch_and_op(&one, &previous, MPI_LONG, 0, slot, add ? MPI_SUM : MPI_NO_OP, window_));
  GF_CALL_MPI(MPI_Win_flush(0, window_));
  return previous;
}

long TaskCounter::next() {
  if (schedule_ == Schedule::Static) return rank_ + size_ * localTaken_++;
  return fetchAdd(0);
}

long TaskCounter::finishOne() {
  ++localFinished_;
  if (schedule_ == Schedule::Static) return localFinished_ * size_;
  return fetchAdd(1) + 1;
}

long TaskCounter::finishedSoFar() {
  if (schedule_ == Schedule::Static) return localFinished_ * size_;
  return fetchAdd(1, false);
}

}  // namespace gradfric::campaign
