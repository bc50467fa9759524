// The slider-force sums of the quiet phase (quiet_phase.hpp), kQuietBatch steps at once: every
// step keeps its own accumulator and the kernel's order of summation, so each sum is the stepped
// run's bit for bit, while the independent steps fill the vector lanes.
#include "gradfric/sbm/quiet_phase.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define GF_QUIET_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define GF_QUIET_CLONES
#endif

namespace gradfric::sbm {

namespace {

// slider: per column [N_b] (rowStride 0) or per block [N_b^2] (rowStride N_b).
GF_QUIET_CLONES void sumRows(int nb, const double* slider, int rowStride, const double* drivenX, const double* drivenY,
                             double* __restrict sumX, double* __restrict sumY) {
  double ax[kQuietBatch] = {}, ay[kQuietBatch] = {};
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) {
      const double k = slider[std::size_t(r) * rowStride + c];
      for (int s = 0; s < kQuietBatch; ++s) {
        ax[s] += k * (drivenX[s] - 0.0);
        ay[s] += k * (drivenY[s] - 0.0);
      }
    }
  for (int s = 0; s < kQuietBatch; ++s) {
    sumX[s] = ax[s];
    sumY[s] = ay[s];
  }
}

}  // namespace

void restSliderForceSums(const LatticeStiffness& stiffness, const Motion& m, std::int64_t first, double* sumX,
                         double* sumY) {
  double drivenX[kQuietBatch], drivenY[kQuietBatch];
  for (int s = 0; s < kQuietBatch; ++s) {
    const double t = double(first + s) * m.timeStep;
    drivenX[s] = m.sliderVelocityX * t;
    drivenY[s] = m.sliderVelocityY * t;
  }
  const int nb = stiffness.blocksPerSide;
  sumRows(nb, stiffness.slider.data(), stiffness.perBlock ? nb : 0, drivenX, drivenY, sumX, sumY);
}

}  // namespace gradfric::sbm
