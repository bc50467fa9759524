// The realisation pool (campaign/realisation_pool.hpp) on 1, 2 and 3 ranks: records come back in
// task order on every rank, bit for bit the same as one rank computing them alone (also -0.0, NaN
// payloads and subnormals, which a sum over ranks would change), under either schedule and any
// hand-out order; a failing task ends the pool on every rank with the same message, never a hang.
#include "gradfric/campaign/realisation_pool.hpp"
#include "gradfric/core/collective_error.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gradfric;
using namespace gradfric::campaign;

namespace {

constexpr int kWidth = 4;

// A record whose bits a careless gather would change: -0.0, a NaN with a payload, a subnormal.
std::vector<double> recordOf(long task) {
  std::uint64_t nanBits = 0x7ff8000000000000ull | static_cast<std::uint64_t>(task + 1);
  double payloadNaN = 0.0;
  std::memcpy(&payloadNaN, &nanBits, sizeof payloadNaN);
  return {static_cast<double>(task), task % 3 == 0 ? -0.0 : std::sin(0.1 * task), payloadNaN,
          std::numeric_limits<double>::denorm_min() * (task + 1)};
}

std::vector<double> alone(long tasks) {
  std::vector<double> all;
  for (long k = 0; k < tasks; ++k) {
    const std::vector<double> r = recordOf(k);
    all.insert(all.end(), r.begin(), r.end());
  }
  return all;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

PoolPlan planOf(long tasks, Schedule schedule, bool reversed) {
  PoolPlan plan;
  plan.tasks = tasks;
  plan.width = kWidth;
  plan.schedule = schedule;
  if (reversed) {
    plan.handOutOrder.resize(tasks);
    std::iota(plan.handOutOrder.rbegin(), plan.handOutOrder.rend(), 0L);
  }
  return plan;
}

// True on every rank when `text` is the same on every rank.
bool sameOnEveryRank(MPI_Comm comm, const std::string& text) {
  unsigned long h = std::hash<std::string>{}(text), low = h, high = h;
  MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UNSIGNED_LONG, MPI_MAX, comm);
  return low == high;
}

// The message every rank caught (empty: no CollectiveError).
std::string failureOf(MPI_Comm comm, const PoolPlan& plan, const PoolTask& task) {
  try {
    (void)runRealisationPool(comm, plan, task);
  } catch (const CollectiveError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RealisationPool, RecordsInTaskOrderOnEveryRank) {
  for (Schedule schedule : {Schedule::Dynamic, Schedule::Static})
    for (bool reversed : {false, true}) {
      const std::vector<double> records = runRealisationPool(PETSC_COMM_WORLD, planOf(23, schedule, reversed), recordOf);
      EXPECT_TRUE(sameBits(records, alone(23))) << "schedule " << int(schedule) << ", reversed " << reversed;
    }
}

TEST(RealisationPool, SameBitsAsOneRank) {
  // The same pool on this rank alone and over all ranks.
  const PoolPlan plan = planOf(31, Schedule::Dynamic, false);
  const std::vector<double> one = runRealisationPool(PETSC_COMM_SELF, plan, recordOf);
  const std::vector<double> all = runRealisationPool(PETSC_COMM_WORLD, plan, recordOf);
  EXPECT_TRUE(sameBits(one, all));
}

TEST(RealisationPool, EveryTaskRunsOnce) {
  std::vector<int> mine(40, 0);
  PoolPlan plan = planOf(40, Schedule::Dynamic, true);
  plan.width = 1;
  (void)runRealisationPool(PETSC_COMM_WORLD, plan, [&](long k) {
    ++mine[k];
    return std::vector<double>{1.0};
  });
  std::vector<int> all(40, 0);
  MPI_Allreduce(mine.data(), all.data(), 40, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  for (int k = 0; k < 40; ++k) EXPECT_EQ(all[k], 1) << "task " << k;
}

TEST(RealisationPool, FewerTasksThanRanksAndNone) {
  EXPECT_TRUE(sameBits(runRealisationPool(PETSC_COMM_WORLD, planOf(1, Schedule::Dynamic, false), recordOf), alone(1)));
  EXPECT_TRUE(sameBits(runRealisationPool(PETSC_COMM_WORLD, planOf(1, Schedule::Static, false), recordOf), alone(1)));
  EXPECT_TRUE(runRealisationPool(PETSC_COMM_WORLD, planOf(0, Schedule::Dynamic, false), recordOf).empty());
}

TEST(RealisationPool, FirstFailureInHandOutOrderOnEveryRank) {
  // Tasks 5 and 11 throw; whoever runs them, every rank reports the first handed out.
  auto failing = [](long k) -> std::vector<double> {
    if (k == 5 || k == 11) throw std::runtime_error("bad realisation " + std::to_string(k));
    return recordOf(k);
  };
  for (Schedule schedule : {Schedule::Dynamic, Schedule::Static}) {
    const std::string forward = failureOf(PETSC_COMM_WORLD, planOf(20, schedule, false), failing);
    EXPECT_NE(forward.find("task 5 failed on rank"), std::string::npos) << forward;
    EXPECT_NE(forward.find("bad realisation 5"), std::string::npos) << forward;
    EXPECT_TRUE(sameOnEveryRank(PETSC_COMM_WORLD, forward));
    const std::string backward = failureOf(PETSC_COMM_WORLD, planOf(20, schedule, true), failing);
    EXPECT_NE(backward.find("bad realisation 11"), std::string::npos) << backward;
    EXPECT_TRUE(sameOnEveryRank(PETSC_COMM_WORLD, backward));
  }
}

TEST(RealisationPool, FailureOnOneRankOnlyReachesAll) {
  // Whatever rank 0 runs throws (an error the other ranks cannot know of): no rank hangs, all
  // throw the same message, which the plan's own wording carries.
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  PoolPlan plan = planOf(9, Schedule::Static, false);
  plan.failure = [](long task, int r, const std::string& what) {
    return "realisation " + std::to_string(task) + " on rank " + std::to_string(r) + ": " + what;
  };
  const std::string message = failureOf(PETSC_COMM_WORLD, plan, [rank](long k) -> std::vector<double> {
    if (rank == 0) throw std::runtime_error("rank 0 ran out of memory");
    return recordOf(k);
  });
  EXPECT_EQ(message, "realisation 0 on rank 0: rank 0 ran out of memory");
}

TEST(RealisationPool, WrongRecordWidthIsAFailure) {
  PoolPlan plan = planOf(6, Schedule::Dynamic, false);
  const std::string message = failureOf(PETSC_COMM_WORLD, plan, [](long k) {
    return k == 4 ? std::vector<double>{1.0} : recordOf(k);
  });
  EXPECT_NE(message.find("task 4 failed"), std::string::npos) << message;
  EXPECT_NE(message.find("a record of 1 values where the pool expects 4"), std::string::npos) << message;
}

TEST(RealisationPool, RefusesAnOrderThatIsNoPermutation) {
  PoolPlan plan = planOf(3, Schedule::Dynamic, false);
  plan.handOutOrder = {0, 2, 2};
  EXPECT_THROW((void)runRealisationPool(PETSC_COMM_WORLD, plan, recordOf), std::logic_error);
}
