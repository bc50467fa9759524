// The specialised elastic kernels: f += -E_c K_hat u_e for every cell, scattered into f, with the
// precomputed box-cell stiffness K_hat (E = 1): one for every cell, or on an edge-graded mesh each
// cell's from a table of shapes (cellShape).
//  - elasticKernel: the dense one, a gather of the 24 element displacements, one 24x24
//    matrix-vector product, a scatter-add (the reference, and the fallback).
//  - elasticKernelBlocked: the same operator in the basis of the box's mirror symmetries. A box
//    cell of an isotropic material is unchanged by the three reflections x -> hx - x (and y, z),
//    so K_hat commutes with them: after a Walsh-Hadamard transform over the 8 corners (node
//    a = i + 2j + 4k, one transform per component) K_hat is block diagonal, 8 blocks of 3 x 3
//    (block chi couples component d at the pattern chi ^ 2^d). That is 72 multiplications
//    instead of 576, plus 2 x 72 additions for the transforms: ~4 x fewer flops. Four cells go
//    through it at once (one cell per SIMD lane); the scatter-add stays cell by cell in cell
//    order, so every node sums its cells' forces in the same order as the dense kernel.
//    The arithmetic inside a cell differs from the dense product: the forces agree to
//    round-off (relative ~1e-16, test FemModel.ReflectionBlockKernelEqualsDenseKernel).
#include "gradfric/fem/elastic_operator.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::fem {

namespace {

// One cell shape (stiffness) for all cells, or the shape of each cell (cellShape: an index into
// the table of 576-value stiffnesses). Inlined into each clone, so the uniform mesh's loop is
// the one it always was.
template <bool Shaped>
__attribute__((always_inline)) inline void denseCells(PetscInt numCells, const PetscInt* cellOffsets,
                                                      const double* cellModulus, const double* stiffnesses,
                                                      const int* cellShape, const double* u, const double* v,
                                                      double beta, double* f, const PetscInt* outOffsets) {
  for (PetscInt c = 0; c < numCells; ++c) {
    const PetscInt* off = cellOffsets + 8 * c;
    const PetscInt* out = (outOffsets ? outOffsets : cellOffsets) + 8 * c;
    const double* stiffness = Shaped ? stiffnesses + 576 * cellShape[c] : stiffnesses;
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
      for (int d = 0; d < 3; ++d) f[out[a] + d] += scale * fe[3 * a + d];
  }
}

}  // namespace

__attribute__((target_clones("avx2", "default")))
void elasticKernel(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus, const double* stiffness,
                   const double* u, const double* v, double beta, double* f, const PetscInt* outOffsets,
                   const int* cellShape) {
  if (cellShape)
    denseCells<true>(numCells, cellOffsets, cellModulus, stiffness, cellShape, u, v, beta, f, outOffsets);
  else
    denseCells<false>(numCells, cellOffsets, cellModulus, stiffness, nullptr, u, v, beta, f, outOffsets);
}

namespace {

// +1 or -1: the Walsh function of pattern s at corner a.
double walsh(int s, int a) { return __builtin_popcount(s & a) % 2 ? -1.0 : 1.0; }

}  // namespace

bool reflectionBlocks(const double* stiffness, std::array<double, 72>* blocks) {
  // T = H K H / 64 in the transformed basis (s, d), H the 8-corner Walsh-Hadamard transform per
  // component (H H = 8 I, so f = H (T (H u)) = K u).
  double largest = 0;
  for (int i = 0; i < 576; ++i) largest = std::max(largest, std::fabs(stiffness[i]));
  double offBlock = 0;
  for (int s = 0; s < 8; ++s)
    for (int d = 0; d < 3; ++d)
      for (int t = 0; t < 8; ++t)
        for (int e = 0; e < 3; ++e) {
          double sum = 0;
          for (int a = 0; a < 8; ++a)
            for (int b = 0; b < 8; ++b) sum += walsh(s, a) * stiffness[24 * (3 * a + d) + 3 * b + e] * walsh(t, b);
          sum /= 64;
          const int chi = s ^ (1 << d);
          if ((t ^ (1 << e)) == chi)
            (*blocks)[9 * chi + 3 * d + e] = sum;
          else
            offBlock = std::max(offBlock, std::fabs(sum));
        }
  return offBlock <= 1e-13 * largest;
}

namespace {

using Lanes = double __attribute__((vector_size(32), aligned(8)));  // four cells, one per lane

inline void walshHadamard(Lanes* x) {  // x[8], in place, unnormalised
  for (int h = 1; h < 8; h <<= 1)
    for (int a = 0; a < 8; ++a)
      if (!(a & h)) {
        const Lanes p = x[a], q = x[a + h];
        x[a] = p + q;
        x[a + h] = p - q;
      }
}

// Blocks of one shape for all cells, or each lane's cell's own (cellShape: an index into the
// table of 72-value blocks); the same arithmetic in every lane either way.
template <bool Shaped>
__attribute__((always_inline)) inline void blockedCells(PetscInt numCells, const PetscInt* cellOffsets,
                                                        const double* cellModulus, const double* blocks,
                                                        const int* cellShape, const double* u, double* f,
                                                        const PetscInt* outOffsets) {
  for (PetscInt c = 0; c < numCells; c += 4) {
    const int lanes = static_cast<int>(std::min<PetscInt>(4, numCells - c));
    const PetscInt* off[4];
    for (int l = 0; l < 4; ++l) off[l] = cellOffsets + 8 * (c + std::min(l, lanes - 1));  // short tail: repeat
    const double* laneBlocks[4] = {blocks, blocks, blocks, blocks};
    if (Shaped)
      for (int l = 0; l < 4; ++l) laneBlocks[l] = blocks + 72 * cellShape[c + std::min(l, lanes - 1)];
    // Four cells of one shape (most of a graded mesh's interior): one block for all lanes.
    const bool oneShape = !Shaped || (laneBlocks[1] == laneBlocks[0] && laneBlocks[2] == laneBlocks[0] &&
                                      laneBlocks[3] == laneBlocks[0]);
    Lanes w[3][8];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d)
        w[d][a] = Lanes{u[off[0][a] + d], u[off[1][a] + d], u[off[2][a] + d], u[off[3][a] + d]};
    for (int d = 0; d < 3; ++d) walshHadamard(w[d]);
    Lanes g[3][8];
    for (int chi = 0; chi < 8; ++chi) {
      const int s0 = chi ^ 1, s1 = chi ^ 2, s2 = chi ^ 4;
      const Lanes x0 = w[0][s0], x1 = w[1][s1], x2 = w[2][s2];
      if (!oneShape) {
        Lanes B[9] = {};  // block chi, each lane its cell's
        for (int i = 0; i < 9; ++i)
          B[i] = Lanes{laneBlocks[0][9 * chi + i], laneBlocks[1][9 * chi + i], laneBlocks[2][9 * chi + i],
                       laneBlocks[3][9 * chi + i]};
        g[0][s0] = B[0] * x0 + B[1] * x1 + B[2] * x2;
        g[1][s1] = B[3] * x0 + B[4] * x1 + B[5] * x2;
        g[2][s2] = B[6] * x0 + B[7] * x1 + B[8] * x2;
      } else {
        const double* B = laneBlocks[0] + 9 * chi;
        g[0][s0] = B[0] * x0 + B[1] * x1 + B[2] * x2;
        g[1][s1] = B[3] * x0 + B[4] * x1 + B[5] * x2;
        g[2][s2] = B[6] * x0 + B[7] * x1 + B[8] * x2;
      }
    }
    for (int d = 0; d < 3; ++d) walshHadamard(g[d]);
    Lanes scale = {};
    for (int l = 0; l < lanes; ++l) scale[l] = -cellModulus[c + l];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) g[d][a] *= scale;
    for (int l = 0; l < lanes; ++l) {
      const PetscInt* out = (outOffsets ? outOffsets : cellOffsets) + 8 * (c + l);
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d) f[out[a] + d] += g[d][a][l];
    }
  }
}

}  // namespace

__attribute__((target_clones("avx2", "default")))
void elasticKernelBlocked(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus,
                          const double* blocks, const double* u, double* f, const PetscInt* outOffsets,
                          const int* cellShape) {
  if (cellShape)
    blockedCells<true>(numCells, cellOffsets, cellModulus, blocks, cellShape, u, f, outOffsets);
  else
    blockedCells<false>(numCells, cellOffsets, cellModulus, blocks, nullptr, u, f, outOffsets);
}

}  // namespace gradfric::fem
