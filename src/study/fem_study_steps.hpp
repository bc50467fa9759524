#pragma once
// The steps of the FEM accuracy-cost study (src/study/fem_study.cpp runs them in order): the
// options, the ladders of settings, their runs, the timed estimates of meshes too big to run.
#include "gradfric/core/options.hpp"
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <mpi.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::study::fem_study {

using Mesh = std::array<int, 3>;  // nx, ny, nz

struct Study {
  Grading grading;
  fem::FemParameters base;
  std::vector<std::string> knobs, integrators;
  std::vector<Mesh> meshes, estimates;
  double meshSafety = 0.3, penaltySafety = 0.5;
  int estimateSteps = 40;
  std::vector<double> safeties, safetiesOther, factors, fineSafeties;
  std::string output;
  bool overwrite = false;
  // The base parameters on another mesh: the derived penalty follows the mesh unless set.
  fem::FemParameters onMesh(const Mesh& m) const;
};

struct Outcome {
  double muS = NAN, muK = NAN, wall = NAN, cpu = NAN, steps = 0, dt = 0, stableDt = 0;
  bool windowComplete = false;
  std::string failure;  // non-empty: the run stopped (blow-up monitor, PETSc error)
};

struct Ladder {
  std::string name, knob, unit, meaning;
  std::vector<double> values;            // the setting of each rung
  std::vector<fem::FemParameters> runs;  // the parameters of each rung
  std::vector<std::string> integrators;  // per rung: gfverlet, rk4, ssp
  std::vector<Outcome> outcomes;
  int reference = -1;  // rung of this ladder used as reference (-1: the first dt ladder's)
};

// nx, ms/step, steps, estimated seconds of a mesh timed by a short run.
using Estimate = std::array<double, 4>;

// The load and the wall time of the whole study, recorded with the parameters.
struct StudyTimer {
  std::string loadStart;
  double start = 0.0;
};

std::optional<Study> readStudy(MPI_Comm comm, RunParameters* record);
std::vector<Ladder> buildLadders(const Study& study);
StudyTimer startStudy(MPI_Comm comm, const std::vector<Ladder>& ladders);
// Collective: every rung on all ranks, one after the other (a run repeated in two ladders once).
void runLadders(MPI_Comm comm, const Study& study, std::vector<Ladder>* ladders);
// Collective: the short timed runs of -study_mesh_estimate.
std::vector<Estimate> runEstimates(MPI_Comm comm, const Study& study, const std::vector<Ladder>& ladders);
void finishStudy(MPI_Comm comm, const StudyTimer& timer, RunParameters* record);

}  // namespace gradfric::study::fem_study
