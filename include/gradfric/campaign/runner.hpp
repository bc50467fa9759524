#pragma once
// One runner for every model's campaign: the pending tasks spread over the ranks of comm in groups
// of `ranksPerRun` (one rank per run for the spring-block model, rank groups for the FEM), handed
// out by a TaskCounter over the groups' leaders (dynamic or static). A group runs a task on its own
// communicator; its leader writes the output (data first, done flag last: ResultsFile::writeTask)
// and only then is the task reported, so a task reported done is in the file. A failure stops its
// group; the others finish theirs, the waiting ranks sleep (core/quiet_wait.hpp), and every rank
// throws the same CollectiveError saying the finished tasks are kept for -resume.
#include "gradfric/campaign/scheduler.hpp"
#include "gradfric/campaign/sweep.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace gradfric::campaign {

// What a model supplies: how one task runs, and what happens around it.
struct ModelAdapter {
  int ranksPerRun = 1;  // must divide the size of comm
  Schedule schedule = Schedule::Dynamic;
  std::string unit = "tasks";  // in the failure message: "the finished <unit> are in ..."
  // Every rank of the task's group: runs it on the group's communicator; the leader's result is
  // written to the file.
  std::function<io::TaskOutput(const Task& task, MPI_Comm group)> run;
  // Every rank of the group, once the task is in the file: `ranHere` tasks this group finished,
  // `finishedAll` over all groups (the leader; -1 elsewhere). Progress lines, test aborts.
  std::function<void(const Task& task, const io::TaskOutput& output, long ranHere, long finishedAll, bool leader)>
      finished;
  // Every leader before it takes a task, with the tasks finished so far over all groups (optional).
  std::function<void(long finishedSoFar)> beforeNext;
  // The failure message of a task that threw `what` on `rank` of `group`.
  std::function<std::string(const Task& task, int group, int rank, const std::string& what)> failure;
};

// What this rank's group ran: tasks and their wall seconds (leaders only; 0 elsewhere).
struct RunnerCount {
  long ran = 0;
  double seconds = 0.0;
};

// Collective over comm: runs `tasks` (the pending ones, in order) and writes each into `file`.
// `resultsPath` is named in the failure message.
RunnerCount runPending(MPI_Comm comm, io::ResultsFile& file, const std::vector<Task>& tasks, const ModelAdapter& model,
                       const std::string& resultsPath);

}  // namespace gradfric::campaign
