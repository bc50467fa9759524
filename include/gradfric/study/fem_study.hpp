#pragma once
// What accuracy costs in time, for the finite-element plate: the error of the global mu_s and mu_k
// and the wall time for ladders of settings (mesh, time-step safety factor per integrator, penalty
// stiffnesses k_n and k_t), each against the finest rung of its ladder (the dt ladders share the
// finest gfverlet rung). Same HDF5 layout as the SBM study (docs/accuracy_fem.md), so
// scripts/plot_accuracy.py draws it.
#include "gradfric/core/options.hpp"

#include <mpi.h>

namespace gradfric::study {

// Reads -study_*, -fem_*, -grading_*, -output*; every run uses all ranks of comm (the FEM is
// MPI-parallel), one after the other; rank 0 writes the file (temporary name, renamed at the end).
void runFiniteElementStudy(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric::study
