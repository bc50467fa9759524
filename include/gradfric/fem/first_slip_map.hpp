#pragma once
// The FEM's first-slip map: the time, since the start of sliding, at which each bottom node's
// committed contact state first was Slip (NaN: it never slid). It is the detachment front's
// history, as the spring-block model's /maps/first_slip_time, on the bottom node grid: where the
// slip nucleates, how it crosses the plate, and which nodes still stick at the peak. Recorded
// only with first_slip in -friction_observables (ContactBoundary::recordFirstSlips); a single
// run writes it as /fem/first_slip/time [ny+1][nx+1] (run_extras.hpp).
#include "gradfric/fem/plate_model.hpp"

#include <vector>

namespace gradfric::fem {

struct FirstSlipMap {
  int nx = 0, ny = 0;                // nodes per row and rows: (fem_nx + 1) x (fem_ny + 1)
  std::vector<double> time;          // [ny][nx] row-major [s]; NaN: never slid
  std::vector<double> nodeX, nodeY;  // the node positions along x (nx) and y (ny) [m]
};

// Collective: every rank's nodes gathered on rank 0 (the other ranks get an empty map).
FirstSlipMap gatherFirstSlipMap(const PlateModel& model);

}  // namespace gradfric::fem
