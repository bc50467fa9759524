// The task counter hands out every index exactly once over all ranks, dynamic or static, also
// with more ranks than tasks; the finished count reaches the number of tasks.
#include "gradfric/campaign/scheduler.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <unistd.h>

#include <vector>

using namespace gradfric::campaign;

namespace {
void checkEveryIndexOnce(Schedule schedule, long tasks) {
  MPI_Comm comm = PETSC_COMM_WORLD;
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> mine(tasks, 0), all(tasks, 0);
  long finishedSeen = 0;
  {
    TaskCounter counter(comm, schedule);
    for (;;) {
      const long i = counter.next();
      if (i >= tasks) break;
      ASSERT_GE(i, 0);
      mine[i] += 1;
      finishedSeen = std::max(finishedSeen, counter.finishOne());
    }
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(tasks), MPI_INT, MPI_SUM, comm);
  for (long i = 0; i < tasks; ++i) EXPECT_EQ(all[i], 1) << "task " << i;
  long maxFinished = 0;
  MPI_Allreduce(&finishedSeen, &maxFinished, 1, MPI_LONG, MPI_MAX, comm);
  if (schedule == Schedule::Dynamic) {
    EXPECT_EQ(maxFinished, tasks);
  } else {
    EXPECT_GE(maxFinished, tasks);
  }
}
}  // namespace

TEST(TaskCounter, DynamicHandsOutEveryIndexOnce) { checkEveryIndexOnce(Schedule::Dynamic, 57); }
TEST(TaskCounter, StaticHandsOutEveryIndexOnce) { checkEveryIndexOnce(Schedule::Static, 57); }
TEST(TaskCounter, MoreRanksThanTasks) {
  checkEveryIndexOnce(Schedule::Dynamic, 1);
  checkEveryIndexOnce(Schedule::Static, 1);
  checkEveryIndexOnce(Schedule::Dynamic, 0);
}
TEST(TaskCounter, DynamicBalancesUnequalWork) {
  // Rank 0 sleeps on each task; the other ranks must take more of the tasks.
  MPI_Comm comm = PETSC_COMM_WORLD;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (size < 2) GTEST_SKIP() << "needs 2 ranks";
  long taken = 0;
  {
    TaskCounter counter(comm, Schedule::Dynamic);
    for (;;) {
      const long i = counter.next();
      if (i >= 40) break;
      ++taken;
      if (rank == 0) usleep(20000);
      counter.finishOne();
    }
  }
  std::vector<long> perRank(size);
  MPI_Allgather(&taken, 1, MPI_LONG, perRank.data(), 1, MPI_LONG, comm);
  long others = 0;
  for (int r = 1; r < size; ++r) others += perRank[r];
  EXPECT_GT(others, perRank[0]);
}
