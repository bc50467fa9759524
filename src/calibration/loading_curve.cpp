// Loading slope and static peak of a mu(t) curve (include/gradfric/calibration/loading_curve.hpp).
#include "gradfric/calibration/loading_curve.hpp"

#include "gradfric/campaign/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::calibration {

LoadingFeatures loadingFeatures(const std::vector<double>& time, const std::vector<double>& mu, const LoadingWindow& window,
                                double peak, double peakTime) {
  LoadingFeatures f;
  const std::size_t n = std::min(time.size(), mu.size());
  if (n == 0) return f;
  if (!std::isfinite(peak)) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (mu[i] > mu[best]) best = i;
    peak = mu[best];
    peakTime = time[best];
  }
  f.peak = peak;
  f.peakTime = peakTime;
  // Least squares over the window, centred on the first sample for conditioning.
  double st = 0, sm = 0, stt = 0, stm = 0;
  int k = 0;
  const double t0 = time[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (time[i] > peakTime) break;
    if (!(mu[i] >= window.low * peak && mu[i] <= window.high * peak)) continue;
    const double t = time[i] - t0;
    st += t;
    sm += mu[i];
    stt += t * t;
    stm += t * mu[i];
    ++k;
  }
  f.samples = k;
  if (k < 2) return f;
  const double sxx = stt - st * st / k;
  if (!(sxx > 0)) return f;
  f.slope = (stm - st * sm / k) / sxx;
  if (k < 3) return f;
  const double intercept = (sm - f.slope * st) / k;
  double ss = 0;  // residual sum of squares, second pass
  for (std::size_t i = 0; i < n; ++i) {
    if (time[i] > peakTime) break;
    if (!(mu[i] >= window.low * peak && mu[i] <= window.high * peak)) continue;
    const double r = mu[i] - (intercept + f.slope * (time[i] - t0));
    ss += r * r;
  }
  f.slopeStdError = std::sqrt(ss / (k - 2) / sxx);
  f.slopeHalfWidth = campaign::t95(k - 2) * f.slopeStdError;  // the fit has k - 2 degrees of freedom
  return f;
}

std::vector<double> interpolate(const std::vector<double>& time, const std::vector<double>& mu,
                                const std::vector<double>& at) {
  std::vector<double> out(at.size(), LoadingFeatures::kNaN);
  const std::size_t n = std::min(time.size(), mu.size());
  if (n == 0) return out;
  std::size_t j = 0;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double t = at[i];
    if (t < time[0] || t > time[n - 1]) continue;
    while (j + 1 < n && time[j + 1] < t) ++j;
    if (j + 1 >= n) {
      out[i] = mu[n - 1];
      continue;
    }
    const double span = time[j + 1] - time[j];
    const double w = span > 0 ? (t - time[j]) / span : 0.0;
    out[i] = (1 - w) * mu[j] + w * mu[j + 1];
  }
  return out;
}

}  // namespace gradfric::calibration
