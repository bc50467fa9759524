#pragma once
// A spring-block scene: every option of a `gradfric` run, read and checked before any work, and
// what follows from them (the sweep, the results file's layout, the attributes it stores).
// The run itself is a sequence of named steps (drivers/gradfric.cpp): readScene, printScene,
// planResultsFile, openResultsFile, runTasks, finishResultsFile, printResults.
#include "gradfric/core/options.hpp"
#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/core/study_table.hpp"
#include "gradfric/campaign/campaign.hpp"
#include "gradfric/io/results_file.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"

#include <mpi.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::ensemble {

// The campaign's record (sweep, grading, results file) plus the spring-block model's options.
// The -field_* property fields are baseGrading.fields (null: none), every point's unless swept.
struct Scene : campaign::Campaign {
  // -ensemble_* and -output* options (the count, the target, resume and extension: the campaign's).
  std::uint64_t seed = 1;  // with commonStreams, realisation r of every point draws from (seed, 0, r)
  bool history = true;         // store the mu(t) histories
  bool frictionFields = false;  // store every realisation's local mu_s,i, mu_k,i
  bool monitor = false;        // a progress line per finished task
  std::string schedule = "dynamic";
  bool dryRun = false;
  long abortAfter = 0;  // testing only: every rank exits abruptly after this many tasks
  // -sbm_* options: one time step for the whole sweep, from its stiffest point.
  sbm::Parameters parameters;
  sbm::Request request;
  double stiffestFactor = 1.0;  // the largest modulus factor of any point

  // The model inputs of sweep point p (its grading: Campaign::pointGrading).
  sbm::Parameters pointParameters(int p) const;
  // Each point's discretisation bar of mu_s (bars[0]) and mu_k (bars[1]): the lattice ladder of
  // the study (docs/sbm_study.tsv) holding the point's scene and N_b (core/study_table.hpp).
  std::vector<study::StudyBar> bars[2];
  const study::StudyBar& discretisation(int p, bool kinetic) const { return bars[kinetic ? 1 : 0][p]; }
};

// Collective: reads and checks every option (InputError on every rank alike); nullopt after -help.
std::optional<Scene> readScene(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric::ensemble
