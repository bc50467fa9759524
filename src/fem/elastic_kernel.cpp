// The specialised elastic kernel: a gather of the 24 element displacements, one 24x24 matrix-vector
// product with the precomputed box-cell stiffness scaled by the cell's E, and a scatter-add.
// Requires a symmetric stiffness (rows are read as columns).
#include "gradfric/fem/elastic_operator.hpp"

namespace gradfric::fem {

__attribute__((target_clones("avx512f", "avx2", "default")))
void elasticKernel(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus, const double* stiffness,
                   const double* u, const double* v, double beta, double* f) {
  for (PetscInt c = 0; c < numCells; ++c) {
    const PetscInt* off = cellOffsets + 8 * c;
    double ue[24];
    if (v && beta != 0.0) {
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d) ue[3 * a + d] = u[off[a] + d] + beta * v[off[a] + d];
    } else {
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d) ue[3 * a + d] = u[off[a] + d];
    }
    // fe = K_hat ue as a sum of columns (K_hat is symmetric): each fe[i] accumulates in the
    // order j = 0..23 like a dot product, but the loop over i vectorises without reordering
    // any sum (no -ffast-math needed, results identical on every clone).
    double fe[24] = {};
    for (int j = 0; j < 24; ++j) {
      const double* column = stiffness + 24 * j;
      const double uj = ue[j];
      for (int i = 0; i < 24; ++i) fe[i] += column[i] * uj;
    }
    const double scale = -cellModulus[c];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) f[off[a] + d] += scale * fe[3 * a + d];
  }
}

}  // namespace gradfric::fem
