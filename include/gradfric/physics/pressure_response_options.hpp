#pragma once
// The -pressure_response options of the spring-block model (physics/pressure_response.hpp):
//   -pressure_response none|moment|fem     the shape g of p_i(t) = p_i^0 (1 + mu(t) g_i)
//   -pressure_response_edge <m>            moment: decay length of the edge concentration
//   -pressure_response_file <run.h5>       fem: a gradfric-fem results file (/fem/pressure_response/g),
//                                          or several, comma-separated, with
//   -pressure_response_select same|grading fem: one g for every sweep point, or per point the file
//                                          whose FEM run had the point's grading (its /scene record)
// PETSc/HDF5 part of the library; docs/fields.md, "The 3D pressure in the spring-block model".
#include "gradfric/core/options.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/pressure_response.hpp"

namespace gradfric {

// The group of g gradfric-fem writes and the SBM reads: /fem/pressure_response in a results file
// of format gradfric-fem-run, /pressure_response in the older gradfric-fem-history files.
inline constexpr const char* kPressureResponseGroup = "/fem/pressure_response";
inline constexpr const char* kOldPressureResponseGroup = "/pressure_response";

// The default decay length of the moment-balance shape, in units of the plate thickness H
// (the FEM-measured g of the paper mesh on 120 x 120 blocks is fitted best by 0.48 H; docs/fields.md).
inline constexpr double kDefaultEdgeOverThickness = 0.5;

// Reads and checks the options on every rank (InputError, before any work): an edge length out
// of (0, L/2], a file that is not a readable map covering the plate or holds a non-finite value,
// an option given for the other source, and a shape that would make some block's pressure
// negative before mu(t) reaches the plate's mean mu_s (every file's).
PressureResponse readPressureResponse(MPI_Comm comm, RunParameters* record, const Plate& plate, int blocksPerSide);

}  // namespace gradfric
