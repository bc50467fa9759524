#pragma once
// A sweep of FEM runs in one command (gradfric-fem with -ensemble_delta, _theta, _property,
// _profile, _field: the ensemble's lists and its sweep construction, ensemble::buildSweep). The ranks are
// split into groups of -fem_sweep_ranks_per_run (MPI_Comm_split); each run has a group's
// sub-communicator to itself. The pending points are handed out round robin over the groups in
// the ensemble's fixed order (ensemble::pendingTasks), so which group runs a point never changes
// a number in the file. Every run lands in one parallel HDF5 file with the ensemble's layout
// (io::ResultsFile, format gradfric-fem-sweep, one realisation per point), planned through
// io::OutputPlan (<output>.partial until complete), resumable with -resume.
#include "gradfric/core/options.hpp"
#include "gradfric/ensemble/sweep.hpp"
#include "gradfric/fem/parameters.hpp"
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
  ensemble::SweepLists lists;
  bool requested = false;  // a list or a -fem_sweep_ option was given: run the sweep
  int ranksPerRun = 1;
  bool resume = false;
  long abortAfter = 0;  // testing only: every rank exits abruptly once its group finished this many runs
};

// Collective: reads the options (-help lists them); InputError on every rank alike.
SweepOptions readSweepOptions(MPI_Comm comm, RunParameters* record);

// Everything a sweep needs, checked before any work.
struct FemSweep {
  FemParameters params;  // the base run (theta of each point from the sweep)
  Grading baseGrading;
  std::vector<std::shared_ptr<const PlateFields>> pointFields;  // per point with -ensemble_field (else empty)
  SweepOptions options;
  ensemble::Sweep sweep;
  io::EnsembleLayout layout;
  io::SweepTable table;
  std::vector<io::Attribute> sceneAttributes;  // /scene: what defines the results
  std::vector<io::Attribute> runAttributes;    // /run: how this session ran them
  std::string output;                          // the results file (-output)

  int points() const { return static_cast<int>(sweep.points.size()); }
  FemParameters pointParameters(int p) const;
  Grading pointGrading(int p) const;
};

// Collective: builds the sweep and refuses (InputError naming the option, on every rank) what
// cannot run: -ensemble_sigma (the FEM has no random dispersion), snapshots or -fem_compare_sbm
// in a sweep, a group size that does not divide the ranks, any point whose time step or run
// length is refused.
FemSweep buildFemSweep(MPI_Comm comm, const FemParameters& params, const Grading& grading,
                       const SweepOptions& options, bool compareSbm, const RunParameters& record);

// Collective over comm: plans the file, runs every pending point on the groups, writes the
// statistics, renames the file into place and prints the table.
void runFemSweep(MPI_Comm comm, const FemSweep& sweep, const RunParameters& record);

}  // namespace gradfric::fem
