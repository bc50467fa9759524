#pragma once
// The steps of a campaign's results file both models share once the runs are in it: the
// observables' P x R tables, the statistics written to /statistics, and the end (complete,
// closed, renamed into place). The model's own steps (planning, creating, its extra columns) stay
// with the model.
#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/campaign/statistics.hpp"
#include "gradfric/io/output_plan.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <vector>

namespace gradfric::campaign {

// Every rank: the P x R table of each observable with statistics (physics/observables.hpp), in
// the table's order, as pointStatistics takes them.
std::vector<std::vector<double>> observableTables(const io::ResultsFile& file);

// Collective: the statistics of every point from the file's P x R tables, written to /statistics.
// `target`: the precision target, if any (adds its columns).
std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, int realisations, const std::vector<int>& reference,
                                             bool commonStreams, const PrecisionTarget* target = nullptr);

// Collective: marks the file complete, closes it and renames it into place.
void finishResultsFile(MPI_Comm comm, io::ResultsFile& file, const io::OutputPlan& plan);

}  // namespace gradfric::campaign
