// The campaign runner (include/gradfric/campaign/runner.hpp).
#include "gradfric/campaign/runner.hpp"

#include "gradfric/campaign/log_events.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/quiet_wait.hpp"

#include <optional>

namespace gradfric::campaign {

namespace {

// The sub-communicator of this rank's group, ranks [g k, (g + 1) k) of comm (k ranks per run), and
// the communicator of the groups' leaders, over which the tasks are counted.
class Groups {
public:
  Groups(MPI_Comm comm, int ranksPerRun) {
    int rank = 0;
    GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
    group_ = rank / ranksPerRun;
    GF_CALL_MPI(MPI_Comm_split(comm, group_, rank, &group_comm_));
    GF_CALL_MPI(MPI_Comm_size(group_comm_, &size_));
    int inGroup = 0;
    GF_CALL_MPI(MPI_Comm_rank(group_comm_, &inGroup));
    leader_ = inGroup == 0;
    GF_CALL_MPI(MPI_Comm_split(comm, leader_ ? 0 : MPI_UNDEFINED, rank, &leaders_));
  }
  ~Groups() {
    if (leaders_ != MPI_COMM_NULL) MPI_Comm_free(&leaders_);
    MPI_Comm_free(&group_comm_);
  }
  Groups(const Groups&) = delete;
  Groups& operator=(const Groups&) = delete;
  MPI_Comm group() const { return group_comm_; }
  MPI_Comm leaders() const { return leaders_; }
  int index() const { return group_; }
  int size() const { return size_; }
  bool leader() const { return leader_; }

private:
  MPI_Comm group_comm_ = MPI_COMM_NULL, leaders_ = MPI_COMM_NULL;
  int group_ = 0, size_ = 1;
  bool leader_ = true;
};

}  // namespace

RunnerCount runPending(MPI_Comm comm, io::ResultsFile& file, const std::vector<Task>& tasks, const ModelAdapter& model,
                       const std::string& resultsPath) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  const Groups groups(comm, model.ranksPerRun);
  RunnerCount count;
  std::string failure;
  {
    std::optional<TaskCounter> counter;
    if (groups.leader()) counter.emplace(groups.leaders(), model.schedule);
    for (;;) {
      long index = 0;
      if (groups.leader()) {
        if (model.beforeNext) model.beforeNext(counter->finishedSoFar());
        index = counter->next();
      }
      if (groups.size() > 1) GF_CALL_MPI(MPI_Bcast(&index, 1, MPI_LONG, 0, groups.group()));
      if (index >= static_cast<long>(tasks.size())) break;
      const Task& task = tasks[index];
      std::string local;  // this rank's error in this task, if any
      io::TaskOutput output;
      try {
        output = model.run(task, groups.group());
        if (groups.leader()) {
          const LogEventScope writing(logEvents().write);
          file.writeTask(output);
        }
      } catch (const std::exception& e) {
        local = model.failure(task, groups.index(), rank, e.what());
      }
      // A group agrees before its next run: an error on one member (the leader's write, say)
      // ends the loop on all of them instead of leaving the others waiting inside the next run.
      if (groups.size() > 1) {
        int failed = local.empty() ? 0 : 1, anyFailed = 0;
        GF_CALL_MPI(MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_MAX, groups.group()));
        if (anyFailed) {
          failure = local;  // the member that failed reports it
          break;
        }
      } else if (!local.empty()) {
        failure = local;
        break;  // the other ranks finish their tasks; everything finished stays in the file
      }
      ++count.ran;
      count.seconds += output.wallSeconds;
      const long finishedAll = groups.leader() ? counter->finishOne() : -1;
      if (model.finished) model.finished(task, output, count.ran, finishedAll, groups.leader());
    }
    // The tail: a group out of tasks sleeps until the last one finishes. Before the counter's
    // window is freed: that free is collective, and MPI waits in it at full speed.
    waitForRanks(comm);
  }
  file.flush();
  try {
    agreeOnError(comm, failure);
  } catch (const CollectiveError& e) {
    file.close();
    throw CollectiveError(std::string(e.what()) + "; the finished " + model.unit + " are in " + resultsPath +
                          ", continue with -resume");
  }
  file.flush();  // sync, barrier, sync: every rank now reads what the others wrote
  if (!groups.leader()) count = RunnerCount{};
  return count;
}

}  // namespace gradfric::campaign
