#pragma once
// A sweep of FEM runs in one command (gradfric-fem with -ensemble_delta, _theta, _property,
// _profile, _field: the ensemble's lists and its sweep construction, campaign::buildSweep), and
// its realisations of the random surface (-ensemble_realisations or -ensemble_target, the same
// surface r at every point, as the spring blocks' common streams). The ranks are
// split into groups of -fem_sweep_ranks_per_run (MPI_Comm_split); each run has a group's
// sub-communicator to itself. The pending points are handed out round robin over the groups in
// the ensemble's fixed order (campaign::pendingTasks), so which group runs a task never changes
// a number in the file. Every run lands in one parallel HDF5 file with the ensemble's layout
// (io::ResultsFile, format gradfric-fem-sweep), planned through io::OutputPlan (<output>.partial
// until complete), resumable with -resume and extensible with -ensemble_extend.
#include "gradfric/core/options.hpp"
#include "gradfric/campaign/campaign.hpp"
#include "gradfric/campaign/realisation_options.hpp"
#include "gradfric/core/study_table.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/fem/simulation.hpp"
#include "gradfric/io/hdf5_attributes.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/grading.hpp"

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace gradfric::fem {

// The -ensemble_ lists and the -fem_sweep_ options of a gradfric-fem command line.
struct SweepOptions {
  campaign::SweepLists lists;
  campaign::RealisationPlan realisations;  // -ensemble_realisations or -ensemble_target*
  bool extend = false;                     // -ensemble_extend
  bool requested = false;  // a list or a -fem_sweep_ option was given: run the sweep
  int ranksPerRun = 1;
  bool resume = false;
  long abortAfter = 0;  // testing only: every rank exits abruptly once its group finished this many runs
};

// Collective: reads the options (-help lists them); InputError on every rank alike.
SweepOptions readSweepOptions(MPI_Comm comm, RunParameters* record);

// Everything a sweep needs, checked before any work.
// The campaign's record (sweep, grading, results file) plus the FEM's base run and sweep options.
struct FemSweep : campaign::Campaign {
  FemParameters params;  // the base run (theta of each point from the sweep)
  SweepOptions options;
  // Each point's discretisation bar of mu_s (bars[0]) and mu_k (bars[1]): femStudyBar.
  std::vector<study::StudyBar> bars[2];

  FemParameters pointParameters(int p) const;  // its grading: Campaign::pointGrading
  FemParameters taskParameters(const campaign::Task& task) const;  // the point's, on the task's surface
};

// Collective: builds the sweep and refuses (InputError naming the option, on every rank) what
// cannot run: -ensemble_sigma (one surface per FEM sweep), realisations without a dispersed
// surface, snapshots or -fem_compare_sbm in a sweep, a group size that does not divide the ranks,
// any task whose time step or run length is refused.
FemSweep buildFemSweep(MPI_Comm comm, const FemParameters& params, const Grading& grading,
                       const SweepOptions& options, bool compareSbm, const RunParameters& record);

// The campaign record of one run (gradfric-fem without a sweep): the sweep's one point, its
// layout named io::kFemRunFormatName, /scene and /run split as a sweep splits them. The results
// file of a single run is this campaign's file plus the run's FEM extras (output.hpp).
FemSweep oneRunCampaign(const FemParameters& params, const Grading& grading, const RunParameters& record);

// The discretisation bar of a run's mu_s or mu_k (observable): the ladder of docs/fem_study.tsv
// holding the run's scene (its record, with a sweep point's grading and angle) and its mesh
// refined in every direction (core/study_table.hpp). It depends on the settings only.
study::StudyBar femStudyBar(const RunParameters& record, const campaign::SweepPoint* point, const FemParameters& q,
                            const std::string& observable);

// Writes each point's bars as the statistics' mu_s and mu_k discretisation columns: a sweep's file
// and a single run's (one point) alike.
void writeErrorBars(io::ResultsFile& file, const FemSweep& s);

// A run's task record for the campaign file (a sweep's point, or a single run's one): its
// observer's summary and history, and its flutter flag (the nodes that slid at mu > 1).
io::TaskOutput taskOutputOf(const FemRunResult& run);

// Whether the user fixed the length of the runs (-fem_slide_time given, or -fem_stop_when_known
// false): then a run may end before its peak is confirmed by design, not by accident.
bool runLengthFixed(const FemParameters& q, const RunParameters& record);

// Collective over comm: plans the file, runs every pending point on the groups, writes the
// statistics, renames the file into place and prints the table. Returns the exit status: 5 when a
// run ended before confirming its peak although its length was not fixed (its mu_s is only the
// largest mu reached), else 0.
int runFemSweep(MPI_Comm comm, const FemSweep& sweep, const RunParameters& record);

}  // namespace gradfric::fem
