// The specialised elastic kernel: a gather of the 24 element displacements, one 24x24 matrix-vector
// product with the precomputed box-cell stiffness scaled by the cell's E, and a scatter-add.
#include "gradfric/fem/plate_model.hpp"

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
    const double scale = -cellModulus[c];
    for (int a = 0; a < 8; ++a) {
      double fe[3];
      for (int d = 0; d < 3; ++d) {
        const double* row = stiffness + (3 * a + d) * 24;
        double s = 0.0;
        for (int j = 0; j < 24; ++j) s += row[j] * ue[j];
        fe[d] = s;
      }
      for (int d = 0; d < 3; ++d) f[off[a] + d] += scale * fe[d];
    }
  }
}

}  // namespace gradfric::fem
