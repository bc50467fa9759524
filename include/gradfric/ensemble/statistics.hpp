#pragma once
// Ensemble statistics of one sweep point, in one place: pure functions, no MPI, no I/O.
#include <vector>

namespace gradfric::ensemble {

struct Summary {
  int count = 0;       // finite values used (NaN entries, e.g. mu_k not requested, are skipped)
  double mean = 0.0;   // NaN if count == 0
  double stdDev = 0.0;     // sample standard deviation (n - 1); NaN if count < 2
  double stdError = 0.0;   // stdDev / sqrt(n); NaN if count < 2
  double ciLow = 0.0;      // 95 % confidence interval of the mean, Student t with n - 1 degrees
  double ciHigh = 0.0;     // of freedom; NaN if count < 2
};

Summary summarise(const std::vector<double>& values);

// The p-quantile of Student's t distribution with dof >= 1 degrees of freedom, 0 < p < 1.
double studentTQuantile(double p, int dof);

// Regularised incomplete beta function I_x(a, b), 0 <= x <= 1, a, b > 0.
double incompleteBeta(double a, double b, double x);

// The paper's relative variation (mu - mu_0) / mu_0 against the reference (non-graded) point,
// with the error propagated from the two standard errors (independent samples):
//   e = sqrt( (se / mu_0)^2 + (mu se_0 / mu_0^2)^2 ).
// For the reference point itself the variation is exactly 0 with error 0.
struct RelativeVariation {
  double value = 0.0;
  double error = 0.0;
};
RelativeVariation relativeVariation(const Summary& point, const Summary& reference, bool isReference);

// The same for paired samples (common random numbers: realisation r of the point and of its
// reference share their random draws). First-order (delta-method) error from the pairs:
//   z_r = x_r / m_0 - m y_r / m_0^2,  e = std(z) / sqrt(n),
// over the realisations finite in both x (the point) and y (the reference). Needs n >= 2 pairs,
// else NaN error.
RelativeVariation pairedRelativeVariation(const std::vector<double>& point, const std::vector<double>& reference);

// Everything the results file and the final table report for one sweep point.
struct PointStatistics {
  Summary muStatic, muKinetic;
  RelativeVariation muStaticRelative, muKineticRelative;  // NaN when the point has no reference
  int finished = 0;           // realisations finished
  int peaksUnconfirmed = 0;   // of those, runs stopped at t_max before the peak was confirmed
};

// Tables are P x R, row-major. reference[p] is the non-graded point of p (p itself for a
// non-graded point) or -1. Only finished realisations (done[i] != 0) count. paired: the relative
// variations use pairedRelativeVariation (scenes run with common random numbers).
std::vector<PointStatistics> pointStatistics(int realisations, const std::vector<int>& reference,
                                             const std::vector<double>& muStatic,
                                             const std::vector<double>& muKinetic,
                                             const std::vector<signed char>& peakConfirmed,
                                             const std::vector<unsigned char>& done, bool paired = false);

}  // namespace gradfric::ensemble
