// The slider-force sums of the quiet phase (quiet_phase.hpp), in the kernels' order of summation
// (slider_sum.hpp), so that each sum is the stepped run's bit for bit. Rows with the same sliders
// (no stiffness per block) have the same row sum at rest: it is computed once per step.
#include "gradfric/sbm/quiet_phase.hpp"

#include "slider_sum.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GF_QUIET_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define GF_QUIET_CLONES
#endif

namespace gradfric::sbm {

namespace {

// The history's sum of the slider forces at rest, k (driven - 0); slider: per column [N_b]
// (rowStride 0) or per block [N_b^2] (rowStride N_b); row: work space [N_b].
GF_QUIET_CLONES double restSum(int nb, const double* slider, int rowStride, double driven, double* __restrict row) {
  double sum = 0.0, rowTotal = 0.0;
  for (int r = 0; r < nb; ++r) {
    if (r == 0 || rowStride != 0) {
      const double* __restrict k = slider + std::size_t(r) * rowStride;
      for (int c = 0; c < nb; ++c) row[c] = sliderForce(k[c], driven, 0.0);
      rowTotal = rowSum(row, nb);
    }
    sum += rowTotal;
  }
  return sum;
}

}  // namespace

void restSliderForceSums(const LatticeStiffness& stiffness, const Motion& m, std::int64_t step, double* row,
                         double& sumX, double& sumY) {
  const int nb = stiffness.blocksPerSide;
  const int rowStride = stiffness.perBlock ? nb : 0;
  const double t = double(step) * m.timeStep;
  sumX = restSum(nb, stiffness.slider.data(), rowStride, m.sliderVelocityX * t, row);
  sumY = restSum(nb, stiffness.slider.data(), rowStride, m.sliderVelocityY * t, row);
}

}  // namespace gradfric::sbm
