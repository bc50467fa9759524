#pragma once
// Private to the fast spring-block kernel: the slider forces and the one order in which they are
// added up for the friction history. The kernels and the quiet phase (quiet_phase.cpp) must agree on it
// bit for bit:
//   - a row's forces go into kSumLanes interleaved partial sums (column c into lane c mod
//     kSumLanes, each in column order), combined pairwise;
//   - the rows' sums are added in row order.
// Independent lanes let the additions overlap (a single chain waits ~4 cycles on each of the
// N_b^2 additions, 10-15 % of a Verlet step) and fill a vector register; the lanes are fixed in
// the source, so every ISA clone adds the same numbers in the same order. A plate whose rows are
// alike (the slider per column) has one row sum at rest: the quiet phase adds it N_b times.
#include "kernel_inline.hpp"

namespace gradfric::sbm {

// The force of block c's slider spring, k (v t_n - u), as every path writes it (the kernels, the
// held tiles and the quiet phase's closed form with u = 0 must agree bit for bit).
GF_ALWAYS_INLINE double sliderForce(double k, double driven, double u) { return k * (driven - u); }

constexpr int kSumLanes = 8;

GF_ALWAYS_INLINE double rowSum(const double* __restrict values, int n) {
  double lane[kSumLanes] = {};
  int c = 0;
  for (; c + kSumLanes <= n; c += kSumLanes)
    for (int j = 0; j < kSumLanes; ++j) lane[j] += values[c + j];
  for (int j = 0; c + j < n; ++j) lane[j] += values[c + j];
  return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
}

}  // namespace gradfric::sbm
