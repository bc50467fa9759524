#pragma once
// The -plate_ options: the plate record read once, validated, and shared by both models.
#include "gradfric/core/options.hpp"
#include "gradfric/physics/plate.hpp"

namespace gradfric {

// Reads and validates -plate_L, _H, _E, _nu, _rho, _p, _v, _theta, _mu_s, _mu_k. The names the
// models used before (-sbm_E, -fem_H, ...) are refused with their new spelling.
Plate readPlate(MPI_Comm comm, RunParameters* record);

}  // namespace gradfric
