// Running the tasks of a scene (include/gradfric/ensemble/task_runner.hpp).
#include "gradfric/ensemble/task_runner.hpp"

#include "gradfric/campaign/campaign_batches.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/random_stream.hpp"
#include "gradfric/campaign/log_events.hpp"
#include "gradfric/ensemble/scene_file.hpp"
#include "gradfric/campaign/runner.hpp"
#include "gradfric/physics/observables.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/sbm/model.hpp"

#include "gradfric/sbm/lattice.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>
#include <cstdlib>

namespace gradfric::ensemble {

// The spring-block campaign is the campaign component's: its names without the prefix, in this file.
using namespace campaign;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// What the results file keeps of one realisation.
io::TaskOutput toTaskOutput(const Task& task, sbm::Result&& result, bool history, double wall, int rank) {
  io::TaskOutput o;
  o.point = task.point;
  o.realisation = task.realisation;
  o.friction = std::move(result.friction);
  if (!history) {  // -ensemble_history false: the scalars only
    o.friction.time.clear();
    o.friction.mu.clear();
    o.friction.forceX.clear();
    o.friction.forceY.clear();
  }
  o.endTime = result.endTime;
  o.steps = result.steps;
  o.redrawnBlocks = result.redrawnBlocks;
  o.firstSlipTime = std::move(result.firstSlipTime);
  for (auto& s : result.snapshots) {
    o.snapshotTime.push_back(s.time);
    o.snapshots.push_back(std::move(s.sigmaXOverP));
  }
  o.wallSeconds = wall;
  o.rank = rank;
  return o;
}

// Runs one realisation: what the file keeps of it.
io::TaskOutput runTask(const Scene& scene, const Task& task, int rank) {
  const auto& events = logEvents();
  const StreamKey key{scene.seed, static_cast<std::uint32_t>(scene.commonStreams ? 0 : task.point),
                      static_cast<std::uint32_t>(task.realisation)};
  std::optional<LogEventScope> timed(std::in_place, events.task);
  const auto start = Clock::now();
  sbm::Result result = sbm::simulate(scene.pointParameters(task.point), scene.pointGrading(task.point),
                                     scene.request, key);
  const double wall = secondsSince(start);
  timed.reset();
  io::TaskOutput o = toTaskOutput(task, std::move(result), scene.history, wall, rank);
  if (scene.frictionFields) {  // the same draw as the run's (a pure function of the stream key)
    const sbm::Parameters q = scene.pointParameters(task.point);
    const Grading grading = scene.pointGrading(task.point);
    const sbm::FrictionField field = sbm::buildFriction(q, grading, key);
    const int nb = q.blocksPerSide;
    const PropertySampler sampler(grading, nb, nb);  // a pressure field (-field_p_*) changes F_n per block
    const bool pressureField = grading.fields && grading.fields->pressure;
    for (int row = 0; row < nb; ++row)
      for (int column = 0; column < nb; ++column) {
        const double normal = pressureField ? q.normalForcePerBlock() * sampler.pressure((column + 0.5) / nb, (row + 0.5) / nb)
                                            : q.normalForcePerBlock();
        o.localStatic.push_back(field.staticAt(row, column) / normal);
        o.localKinetic.push_back(field.kineticAt(row, column) / normal);
      }
  }
  return o;
}

void printProgress(const Task& task, const io::TaskOutput& o, double wall, long finishedAll, long pending,
                   long alreadyDone, long total, const Sweep& sweep, double elapsed, int rank) {
  const long left = pending - finishedAll;
  const double eta = finishedAll > 0 ? elapsed * left / finishedAll : NAN;
  std::printf("[%ld/%ld] point %d (%s) realisation %d: %s%s  task %.2f s on rank %d;"
              " elapsed %s, left ~%s\n",
              finishedAll + alreadyDone, total, task.point, pointLabel(sweep, task.point).c_str(), task.realisation,
              observablesText(o.friction).c_str(), o.friction.peakConfirmed ? "" : " (peak unconfirmed)", wall, rank,
              hms(elapsed).c_str(), left > 0 ? hms(eta).c_str() : "0:00:00");
  std::fflush(stdout);
}

// -ensemble_abort_after (testing only): every rank exits abruptly, as a killed job would.
void abortIfDue(const Scene& scene, long finishedOverall, int rank) {
  if (scene.abortAfter <= 0 || finishedOverall < scene.abortAfter) return;
  std::printf("ensemble: -ensemble_abort_after %ld reached: rank %d exits abruptly (test of resume)\n",
              scene.abortAfter, rank);
  std::fflush(stdout);
  std::_Exit(86);
}

// One batch of tasks over the ranks (the campaign runner, one rank per realisation). `before`
// counts the tasks this run finished in earlier batches, `total` is the progress line's denominator.
void runBatch(MPI_Comm comm, const Scene& scene, io::ResultsFile& file, const std::vector<Task>& tasks,
              const std::string& resultsPath, long before, long total, TaskTally* tally, long* ranHere,
              double* secondsHere) {
  int rank = 0;
  GF_CALL_MPI(MPI_Comm_rank(comm, &rank));
  ModelAdapter model;
  model.schedule = scene.schedule == "dynamic" ? Schedule::Dynamic : Schedule::Static;
  model.run = [&](const Task& task, MPI_Comm) { return runTask(scene, task, rank); };
  model.finished = [&](const Task& task, const io::TaskOutput& o, long, long finishedAll, bool) {
    if (scene.monitor)
      printProgress(task, o, o.wallSeconds, before + finishedAll, before + static_cast<long>(tasks.size()),
                    tally->alreadyDone, total, scene.sweep, secondsSince(tally->start), rank);
    abortIfDue(scene, before + finishedAll, rank);
  };
  if (scene.abortAfter > 0) model.beforeNext = [&](long finishedSoFar) { abortIfDue(scene, before + finishedSoFar, rank); };
  model.failure = [](const Task& task, int, int rank, const std::string& what) {
    return "task (point " + std::to_string(task.point) + ", realisation " + std::to_string(task.realisation) +
           ") failed on rank " + std::to_string(rank) + ": " + what;
  };
  const RunnerCount count = runPending(comm, file, tasks, model, resultsPath);
  *ranHere += count.ran;
  *secondsHere += count.seconds;
}

}  // namespace

TaskTally runTasks(MPI_Comm comm, const Scene& scene, io::ResultsFile& file, const std::string& resultsPath) {
  TaskTally tally;
  long ranHere = 0;
  double secondsHere = 0.0;
  tally.alreadyDone += file.finishedCount();  // the progress lines count them
  runCampaignBatches(comm, scene, file, [&](const std::vector<Task>& tasks, long before, long planned) {
    runBatch(comm, scene, file, tasks, resultsPath, before, planned, &tally, &ranHere, &secondsHere);
  });
  GF_CALL_MPI(MPI_Allreduce(&ranHere, &tally.ran, 1, MPI_LONG, MPI_SUM, comm));
  GF_CALL_MPI(MPI_Allreduce(&secondsHere, &tally.taskSeconds, 1, MPI_DOUBLE, MPI_SUM, comm));
  return tally;
}

}  // namespace gradfric::ensemble
