#pragma once
// Running the tasks of a scene: every (sweep point, realisation) not yet in the results file, over
// the ranks of comm (dynamic or static schedule); each finished task is written to the file by the
// rank that ran it. A task that fails (the blow-up monitor) stops its rank; the ranks agree on the
// failure and every rank throws the same CollectiveError (the finished tasks stay in the file,
// resumable).
#include "gradfric/ensemble/scene.hpp"
#include "gradfric/ensemble/scene_report.hpp"
#include "gradfric/io/results_file.hpp"

#include <mpi.h>

namespace gradfric::ensemble {

// Collective. `resultsPath` is named in the failure message (where the finished tasks are).
TaskTally runTasks(MPI_Comm comm, const Scene& scene, io::ResultsFile& file, const std::string& resultsPath);

}  // namespace gradfric::ensemble
