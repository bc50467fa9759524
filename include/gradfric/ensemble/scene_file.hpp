#pragma once
// The results file of a spring-block scene run: planned before any work (io::OutputPlan: the
// final path, <output>.partial while the run writes), created or resumed (a file to continue is
// checked first: one clear message, never HDF5's error stack), completed with the statistics and
// renamed into place only when the run succeeded.
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/ensemble/statistics.hpp"
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

// What a file to resume must match, for any writer of the ensemble layout (the spring-block
// scene above, the FEM sweep): its /scene record and layout (format included), and the options
// the messages name.
struct ResumeTarget {
  std::vector<io::Attribute> sceneAttributes;
  io::EnsembleLayout layout;
  std::string resumeOption = "-resume";
  std::string overwriteOption = "-output_overwrite";
};
void checkResumable(MPI_Comm comm, const ResumeTarget& target, const std::string& path);

// Collective: the same for a finished file to extend (-ensemble_extend): complete, of this scene
// apart from the count, the target and appended sweep values, its points the first of the
// scene's sweep and its realisations the first of each point.
void checkExtendable(MPI_Comm comm, const Scene& scene, const std::string& path);

// Collective: a new file (every dataset allocated) or the checked file to resume; the run's
// attributes (/run) are set.
io::ResultsFile openResultsFile(MPI_Comm comm, const Scene& scene, const io::OutputPlan& plan);

// Every rank: the P x R table of each observable with statistics (physics/observables.hpp), in
// the table's order, as pointStatistics takes them.
std::vector<std::vector<double>> observableTables(const io::ResultsFile& file);

// Collective: the statistics of every point from the file's P x R tables, written to /statistics.
std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, const Scene& scene);
// The same from what the statistics depend on (the FEM sweep: one realisation per point).
// `target`: the scene's precision target, if any (adds its columns).
std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, int realisations,
                                             const std::vector<int>& reference, bool commonStreams,
                                             const PrecisionTarget* target = nullptr);

// Collective: marks the file complete, closes it and renames it into place.
void finishResultsFile(MPI_Comm comm, io::ResultsFile& file, const io::OutputPlan& plan);

}  // namespace gradfric::ensemble
