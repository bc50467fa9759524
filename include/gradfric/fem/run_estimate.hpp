#pragma once
// What a FEM run will cost, known before the mesh is built: cells, unknowns, memory, steps and
// wall time. Printed before every run, and alone with -fem_dry_run (a huge mesh no longer starts
// silently).
#include "gradfric/fem/parameters.hpp"
#include "gradfric/physics/grading.hpp"

#include <string>

namespace gradfric::fem {

struct RunEstimate {
  long long cells = 0, vertices = 0, unknowns = 0;  // unknowns: 6 per vertex (displacement, velocity)
  double rankZeroMemory = 0;                       // [bytes] the serial mesh is built on rank 0 first
  long long pressureSteps = 0, slidingSteps = 0;   // sliding: the most, -fem_slide_time / dt
  double wallSeconds = 0;                          // pressure + all the sliding steps, on `ranks` ranks
  int ranks = 1;
  std::string describe() const;  // one paragraph, with the measured rates it rests on
};

// Throws InputError as chooseTimeStep does.
RunEstimate estimateRun(const FemParameters& params, const Grading& grading, int ranks);

}  // namespace gradfric::fem
