#pragma once
// The -surface_ options: the random surface record (physics/random_surface.hpp), read once,
// validated, and shared by both models.
#include "gradfric/core/options.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/random_surface.hpp"

namespace gradfric {

// The model's default dispersion: the paper's spring blocks have 2.8 % (paper, "2D spring-block
// model"), its 3D model none.
struct SurfaceDefaults {
  double sigma = 0.0;
  bool blocksAllowed = false;  // -surface_kind blocks: the spring-block lattice's own draws
};

// Reads and validates -surface_sigma_s, _sigma_k, _kind and _length (default L/120, recorded as
// derived). The seed is the run's (-ensemble_seed): a realisation is (seed, realisation). The
// spring blocks' old -sbm_sigma_s/_k are refused with the new spelling.
SurfaceSettings readSurface(MPI_Comm comm, RunParameters* record, const Plate& plate, const SurfaceDefaults& defaults);

}  // namespace gradfric
