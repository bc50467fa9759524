#pragma once
// What a spring-block scene run prints: the plan before any work, the statistics and the cost
// after it (rank 0 prints; every rank calls).
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/campaign/statistics.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace gradfric::ensemble {

// What the tasks cost, summed over the ranks.
struct TaskTally {
  long alreadyDone = 0;        // tasks finished by an earlier run (resume)
  long ran = 0;                // tasks run now, all ranks
  double taskSeconds = 0.0;    // their wall time, summed
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();  // of the tasks
};

// The resolved parameters, the active effects and the sweep.
void printScene(MPI_Comm comm, const Scene& scene, const RunParameters& record);
void printDryRun(MPI_Comm comm, const Scene& scene);
// The statistics table (or the single result) and the cost line.
void printResults(MPI_Comm comm, const Scene& scene, const std::vector<campaign::PointStatistics>& statistics,
                  const TaskTally& tally, const std::string& resultsPath);

}  // namespace gradfric::ensemble
