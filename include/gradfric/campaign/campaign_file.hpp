#pragma once
// The steps of a campaign's results file both models share: planned before any work
// (io::OutputPlan: <output>.partial while the runs write), created, resumed or extended (a file to
// continue is checked first: one clear message, never HDF5's error stack), the observables' P x R
// tables, the statistics written to /statistics, and the end (complete, closed, renamed into
// place). The model's own columns and printouts stay with the model.
#include "gradfric/campaign/campaign.hpp"
#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/campaign/statistics.hpp"
#include "gradfric/io/output_plan.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <string>
#include <vector>

namespace gradfric::campaign {

// Collective: the plan of c.output with c.resume, c.extend (-ensemble_extend) and c.overwrite;
// refuses (InputError on every rank) what the plan refuses.
io::OutputPlan planCampaignFile(MPI_Comm comm, const Campaign& c);

// Collective: a new file (every dataset allocated), the checked file to resume (its format,
// version, layout and every option of /scene), or a new file holding the tasks of the finished
// file to extend (of this campaign apart from the count, the target and appended sweep values;
// its points the first of the sweep and its realisations the first of each point). The run's
// attributes (/run) are set. `unit` names the tasks in the messages ("tasks", "runs").
io::ResultsFile openCampaignFile(MPI_Comm comm, const Campaign& c, const io::OutputPlan& plan, const std::string& unit);

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
