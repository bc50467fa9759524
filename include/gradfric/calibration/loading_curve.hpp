#pragma once
// What a calibration compares of two mu(t) curves: the loading slope, the least-squares slope of
// mu against t over the samples before the peak with lo mu_s <= mu <= hi mu_s (0.2-0.6 by
// default, as docs/accuracy_fem.md measures the FEM's slope), and the static peak. Pure
// functions, no MPI.
#include <limits>
#include <vector>

namespace gradfric::calibration {

struct LoadingWindow {
  double low = 0.2;   // fraction of the peak where the fit starts
  double high = 0.6;  // ... and ends
};

struct LoadingFeatures {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double peak = kNaN;      // mu_s: the static peak
  double peakTime = kNaN;  // its time [s]
  double slope = kNaN;     // d mu / dt over the window [1/s]
  double slopeStdError = kNaN;  // the fit's standard error [1/s] (NaN below 3 samples)
  double slopeHalfWidth = kNaN;  // its 95 % Student t half-width, t(0.975, samples - 2) x slopeStdError [1/s]
  int samples = 0;              // samples in the window
};

// The features of one curve. `peak` and `peakTime`: the model's own measurement of the static
// peak if it has one (NaN: the maximum of mu over the curve and its first time).
LoadingFeatures loadingFeatures(const std::vector<double>& time, const std::vector<double>& mu, const LoadingWindow& window,
                                double peak = LoadingFeatures::kNaN, double peakTime = LoadingFeatures::kNaN);

// mu(t) linearly interpolated at each of `at` (increasing); NaN outside [time.front(), time.back()].
std::vector<double> interpolate(const std::vector<double>& time, const std::vector<double>& mu,
                                const std::vector<double>& at);

}  // namespace gradfric::calibration
