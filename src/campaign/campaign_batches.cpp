// The batches of a campaign (include/gradfric/campaign/campaign_batches.hpp).
#include "gradfric/campaign/campaign_batches.hpp"

#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <algorithm>
#include <string>

namespace gradfric::campaign {

namespace {

std::vector<unsigned char> doneFlags(const io::ResultsFile& file) {
  const auto flags = file.finishedTasks();
  return std::vector<unsigned char>(flags.begin(), flags.end());
}

// A precision target: batches until every point meets it or reaches the cap.
void runToTarget(MPI_Comm comm, const Campaign& c, io::ResultsFile& file, const BatchRunner& runBatch) {
  std::vector<int> counts(c.points(), std::min(c.target.first, c.target.cap));
  long ranBefore = 0;
  for (int batch = 0;;) {
    const std::vector<unsigned char> done = doneFlags(file);
    const std::vector<Task> tasks = pendingTasks(c.sweep, c.realisations, done, counts);
    if (!tasks.empty()) {
      long planned = 0;
      std::string perPoint;
      for (int n : counts) {
        planned += n;
        perPoint += " " + std::to_string(n);
      }
      GF_CALL(PetscPrintf(comm, "Target batch %d: %zu task(s) to run; realisations per point:%s\n", batch,
                          tasks.size(), perPoint.c_str()));
      runBatch(tasks, ranBefore, planned);
      ranBefore += static_cast<long>(tasks.size());
      ++batch;
      continue;  // the same batch again: now complete, its statistics decide the next
    }
    const auto statistics = statisticsOfCounts(counts, c.realisations, c.sweep.reference, observableTables(file),
                                               file.readPeakConfirmed(), done, c.commonStreams);
    const std::vector<int> next = planNextBatch(c.target, counts, statistics, c.sweep.reference);
    if (next == counts) return;
    counts = next;
  }
}

}  // namespace

void runCampaignBatches(MPI_Comm comm, const Campaign& c, io::ResultsFile& file, const BatchRunner& runBatch) {
  if (c.target.active())
    runToTarget(comm, c, file, runBatch);
  else
    runBatch(pendingTasks(c.sweep, c.realisations, doneFlags(file)), 0, c.tasks());
}

}  // namespace gradfric::campaign
