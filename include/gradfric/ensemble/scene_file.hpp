#pragma once
// The results file of a spring-block scene run: planned before any work (io::OutputPlan: the
// final path, <output>.partial while the run writes), created or resumed (a file to continue is
// checked first: one clear message, never HDF5's error stack), completed with the statistics and
// renamed into place only when the run succeeded.
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/campaign/campaign_file.hpp"
#include "gradfric/io/output_plan.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

#include <vector>

namespace gradfric::ensemble {

// Collective: refuses (InputError on every rank) what the plan refuses.
io::OutputPlan planResultsFile(MPI_Comm comm, const Scene& scene);

// Collective: on rank 0, checks that the file to resume is a results file of this scene (format,
// version, layout, every option of /scene) and throws InputError naming -resume and
// what is wrong with the file on every rank otherwise.
void checkResumable(MPI_Comm comm, const Scene& scene, const std::string& path);

// Collective: the same for a finished file to extend (-ensemble_extend): complete, of this scene
// apart from the count, the target and appended sweep values, its points the first of the
// scene's sweep and its realisations the first of each point.
void checkExtendable(MPI_Comm comm, const Scene& scene, const std::string& path);

// Collective: a new file (every dataset allocated) or the checked file to resume; the run's
// attributes (/run) are set.
io::ResultsFile openResultsFile(MPI_Comm comm, const Scene& scene, const io::OutputPlan& plan);

// Collective: the statistics of every point from the file's P x R tables, written to /statistics.
std::vector<campaign::PointStatistics> writeStatistics(io::ResultsFile& file, const Scene& scene);
// The shared steps (observableTables, the generic writeStatistics, finishResultsFile) are the
// campaign's: campaign/campaign_file.hpp.

}  // namespace gradfric::ensemble
