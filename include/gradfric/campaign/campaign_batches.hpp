#pragma once
// Which tasks a campaign runs, in which batches, for either model: every pending task of a fixed
// count at once, or the precision target's batches (precision_target.hpp) until every point meets
// the target or reaches the cap. The plan is replayed from the first batch on the file's values,
// so a resumed run takes the same decisions, and each batch runs only what the file lacks.
#include "gradfric/campaign/campaign.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <functional>
#include <vector>

namespace gradfric::campaign {

// Runs one batch of tasks into the file (the model's runner over its ranks); `before` counts the
// tasks this run finished in earlier batches, `planned` is this run's total so far (progress lines).
using BatchRunner = std::function<void(const std::vector<Task>& tasks, long before, long planned)>;

// Collective: runs the campaign's pending tasks in batches.
void runCampaignBatches(MPI_Comm comm, const Campaign& c, io::ResultsFile& file, const BatchRunner& runBatch);

}  // namespace gradfric::campaign
