#pragma once
// Ensemble statistics of one sweep point, in one place: pure functions, no MPI, no I/O (part of the
// PETSc-free core).
//
// One convention for every interval printed or stored (docs/ensemble.md, section 3): a 95 %
// interval, the Student t half-width t(0.975, dof) x standard error. dof = n - 1 for a mean; for a
// relative variation (a ratio of two means) the propagated standard error times the t quantile of
// the smaller sample's n - 1 (independent samples) or of the pairs' n - 1 (common random numbers).
#include <string>
#include <vector>

namespace gradfric::campaign {

struct Summary {
  int count = 0;       // finite values used (NaN entries, e.g. mu_k not requested, are skipped)
  double mean = 0.0;   // NaN if count == 0
  double stdDev = 0.0;     // sample standard deviation (n - 1); NaN if count < 2
  double stdError = 0.0;   // stdDev / sqrt(n); NaN if count < 2
  double ciLow = 0.0;      // 95 % confidence interval of the mean, Student t with n - 1 degrees
  double ciHigh = 0.0;     // of freedom; NaN if count < 2
  double ciHalfWidth() const { return 0.5 * (ciHigh - ciLow); }
};

Summary summarise(const std::vector<double>& values);

// The p-quantile of Student's t distribution with dof >= 1 degrees of freedom, 0 < p < 1.
double studentTQuantile(double p, int dof);

// The two-sided 95 % Student t factor t(0.975, dof); NaN for dof < 1.
double t95(int dof);

// How every interval is named in printouts and files.
inline constexpr const char* kIntervalName = "95 % Student t half-width";

// Regularised incomplete beta function I_x(a, b), 0 <= x <= 1, a, b > 0.
double incompleteBeta(double a, double b, double x);

// The paper's relative variation (mu - mu_0) / mu_0 against the reference (non-graded) point,
// with the error propagated from the two standard errors (independent samples):
//   e = sqrt( (se / mu_0)^2 + (mu se_0 / mu_0^2)^2 ),
// and its 95 % half-width t95(min(n, n_0) - 1) e (the smaller sample's degrees of freedom).
// For the reference point itself the variation is exactly 0 with error 0.
struct RelativeVariation {
  double value = 0.0;
  double error = 0.0;      // propagated standard error
  double halfWidth = 0.0;  // 95 % Student t half-width (what is printed and stored)
};
RelativeVariation relativeVariation(const Summary& point, const Summary& reference, bool isReference);

// The same for paired samples (common random numbers: realisation r of the point and of its
// reference share their random draws). First-order (delta-method) error from the pairs:
//   z_r = x_r / m_0 - m y_r / m_0^2,  e = std(z) / sqrt(n),
// over the realisations finite in both x (the point) and y (the reference), half-width
// t95(n - 1) e. Needs n >= 2 pairs, else NaN error.
RelativeVariation pairedRelativeVariation(const std::vector<double>& point, const std::vector<double>& reference);

// The statistics of one observable at one sweep point.
struct ObservableStatistics {
  Summary summary;
  RelativeVariation relative;  // NaN when the point has no reference
};

// Everything the results file and the final table report for one sweep point.
struct PointStatistics {
  // One per table given to pointStatistics, in its order (the file's and the printouts' order:
  // statisticsObservables(), physics/observables.hpp).
  std::vector<ObservableStatistics> observables;
  int finished = 0;           // realisations finished
  int peaksUnconfirmed = 0;   // of those, runs stopped at t_max before the peak was confirmed
};

// Tables are P x R, row-major, one per observable. reference[p] is the non-graded point of p (p
// itself for a non-graded point) or -1. Only finished realisations (done[i] != 0) count. paired:
// the relative variations use pairedRelativeVariation (scenes run with common random numbers).
std::vector<PointStatistics> pointStatistics(int realisations, const std::vector<int>& reference,
                                             const std::vector<std::vector<double>>& tables,
                                             const std::vector<signed char>& peakConfirmed,
                                             const std::vector<unsigned char>& done, bool paired = false);

}  // namespace gradfric::campaign
