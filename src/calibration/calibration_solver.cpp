// The secant (Broyden) solve of a calibration (include/gradfric/calibration/calibration.hpp).
#include "gradfric/calibration/calibration.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace gradfric::calibration {

namespace {

// The two residuals: the slope ratio minus 1 and the peak difference.
struct Residual {
  double slope = 0.0, peak = 0.0;
};

Residual residualOf(const Calibration& c, const Evaluation& e) {
  return {e.slope.mean / c.target.slope - 1.0, e.peak.mean - c.target.peak};
}

double halfWidth(const campaign::Summary& s) { return s.ciHalfWidth(); }

// How far an evaluation is from convergence: <= 1 when the fitted residuals are within tolerance.
double misfit(const Calibration& c, const Evaluation& e) {
  const Residual r = residualOf(c, e);
  if (c.settings.fit == Fit::Layer) return std::fabs(r.slope) / c.settings.slopeTolerance;
  // (an ensemble without dispersion has no CI: then 1e-4 of mu)
  const double peakTolerance = c.settings.peakTolerance * std::max(halfWidth(e.peak), 1e-4);
  return std::max(std::fabs(r.slope) / c.settings.slopeTolerance, std::fabs(r.peak) / peakTolerance);
}

void printEvaluation(MPI_Comm comm, const Calibration& c, int k, const Evaluation& e) {
  const Residual r = residualOf(c, e);
  GF_CALL(PetscPrintf(comm,
                      "  %2d  l_z %.6e m  sigma %.5f | slope %.6e 1/s (%+.3f %%)  peak %.6f +- %.6f (%+.6f)%s  %.2f s\n",
                      k, e.layerThickness, e.sigma, e.slope.mean, 100 * r.slope, e.peak.mean, halfWidth(e.peak), r.peak,
                      e.unconfirmed ? "  (peaks unconfirmed)" : "", e.wallSeconds));
}

// The evaluation reported: the one closest to convergence, and whether it converged.
void settleOnBest(const Calibration& c, CalibrationResult* out) {
  out->best = 0;
  for (int k = 1; k < static_cast<int>(out->evaluations.size()); ++k)
    if (misfit(c, out->evaluations[k]) < misfit(c, out->evaluations[out->best])) out->best = k;
  out->converged = misfit(c, out->fitted()) <= 1.0;
}

// The slope's 95 % half-width relative to the reference's slope: the SBM ensemble's and the
// reference fit's, in quadrature.
double relativeSlopeHalfWidth(const Calibration& c, const Evaluation& e) {
  return std::hypot(halfWidth(e.slope), (std::isfinite(c.target.slopeHalfWidth) ? c.target.slopeHalfWidth : 0.0)) /
         c.target.slope;
}

// l_z alone, on the scene's surface: Newton steps on slope ~ 1/l_z (exact while every block
// sticks through the window), with the secant of the last two evaluations as the derivative.
CalibrationResult calibrateLayer(MPI_Comm comm, const Calibration& c, CalibrationResult out, double wall0) {
  const CalibrationSettings& s = c.settings;
  const double lz0 = s.layerGuess;
  auto evaluate = [&](double a) {
    out.evaluations.push_back(evaluateSpringBlocks(comm, c.scene, a * lz0, std::nullopt, c.grid));
    out.realisations += c.scene.realisations;
    printEvaluation(comm, c, static_cast<int>(out.evaluations.size()) - 1, out.evaluations.back());
    return residualOf(c, out.evaluations.back());
  };
  double x = 1.0;
  Residual f = evaluate(x);
  double slopeDerivative = -(1.0 + f.slope) / x, peakDerivative = 0.0;  // d/da of (slope ratio, peak)
  while (misfit(c, out.evaluations.back()) > 1.0 && static_cast<int>(out.evaluations.size()) < s.maxEvaluations) {
    const double a = std::clamp(x * (1.0 + f.slope), 0.25, 4.0);
    if (std::fabs(a - x) < 1e-12) break;  // pinned at a bound
    const Residual g = evaluate(a);
    slopeDerivative = (g.slope - f.slope) / (a - x);
    peakDerivative = (g.peak - f.peak) / (a - x);
    x = a;
    f = g;
  }
  settleOnBest(c, &out);
  const Evaluation& e = out.fitted();
  out.jacobian[0][0] = slopeDerivative / lz0;
  out.jacobian[1][0] = peakDerivative / lz0;
  if (std::fabs(out.jacobian[0][0]) > 0) out.layerError = relativeSlopeHalfWidth(c, e) / std::fabs(out.jacobian[0][0]);
  out.wallSeconds = MPI_Wtime() - wall0;
  return out;
}

}  // namespace

CalibrationResult calibrate(MPI_Comm comm, const Calibration& c) {
  CalibrationResult out;
  const double wall0 = MPI_Wtime();
  GF_CALL(PetscPrintf(comm, "Evaluations (%d realisations each; residuals against the reference):\n",
                      c.scene.realisations));
  if (c.settings.fit == Fit::Layer) return calibrateLayer(comm, c, std::move(out), wall0);
  const CalibrationSettings& s = c.settings;
  const double lz0 = s.layerGuess;
  // Variables scaled to order one: a = l_z / l_z0, b = sigma / sigma_step.
  auto evaluate = [&](double a, double b) {
    out.evaluations.push_back(evaluateSpringBlocks(comm, c.scene, a * lz0, b * s.sigmaStep, c.grid));
    out.realisations += c.scene.realisations;
    printEvaluation(comm, c, static_cast<int>(out.evaluations.size()) - 1, out.evaluations.back());
    return residualOf(c, out.evaluations.back());
  };
  double x[2] = {1.0, s.sigmaGuess / s.sigmaStep};
  Residual f = evaluate(x[0], x[1]);
  // The Jacobian of (slope ratio - 1, peak) in (a, b): the sticking slope goes as 1/l_z; the peak's
  // sigma derivative comes from the first secant step, its l_z derivative from the Broyden updates.
  double J[2][2] = {{-(1.0 + f.slope) / x[0], 0.0}, {0.0, 0.0}};
  {
    const double a = x[0] * (1.0 + f.slope);  // Newton on the 1/l_z slope
    const double b = std::clamp(x[1] + (f.peak > 0 ? 1.0 : -1.0), 0.0, 0.5 / s.sigmaStep);
    if (misfit(c, out.evaluations.back()) > 1.0) {
      const Residual g = evaluate(a, b);
      J[0][0] = -(1.0 + g.slope) / a;
      J[1][1] = b != x[1] ? (g.peak - f.peak) / (b - x[1]) : 0.0;
      x[0] = a;
      x[1] = b;
      f = g;
    }
  }
  if (!(J[1][1] < 0.0)) J[1][1] = -0.01;  // the peak falls as sigma grows; a flat secant is not trusted
  while (misfit(c, out.evaluations.back()) > 1.0 && static_cast<int>(out.evaluations.size()) < s.maxEvaluations) {
    // Newton step on the current Jacobian, kept inside l_z0/4 .. 4 l_z0 and 0 <= sigma <= 0.5.
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(std::fabs(det) > 0)) break;
    double dx[2] = {-(J[1][1] * f.slope - J[0][1] * f.peak) / det, -(-J[1][0] * f.slope + J[0][0] * f.peak) / det};
    const double a = std::clamp(x[0] + dx[0], 0.25, 4.0), b = std::clamp(x[1] + dx[1], 0.0, 0.5 / s.sigmaStep);
    dx[0] = a - x[0];
    dx[1] = b - x[1];
    if (std::fabs(dx[0]) < 1e-9 && std::fabs(dx[1]) < 1e-9) break;  // pinned at a bound, or nowhere to go
    const Residual g = evaluate(a, b);
    // Broyden's update: the secant condition along the step just taken.
    const double df[2] = {g.slope - f.slope, g.peak - f.peak};
    const double norm = dx[0] * dx[0] + dx[1] * dx[1];
    for (int i = 0; i < 2; ++i) {
      const double miss = df[i] - (J[i][0] * dx[0] + J[i][1] * dx[1]);
      for (int j = 0; j < 2; ++j) J[i][j] += miss * dx[j] / norm;
    }
    if (!(J[1][1] < 0.0)) J[1][1] = -0.01;
    x[0] = a;
    x[1] = b;
    f = g;
  }
  settleOnBest(c, &out);
  const Evaluation& e = out.fitted();
  // Unreachable: at a sigma bound the peak is still on the far side of the reference's.
  for (const Evaluation& b : out.evaluations) {
    const Residual r = residualOf(c, b);
    const bool atZero = b.sigma <= 0.0 && r.peak < 0.0, atTop = b.sigma >= 0.5 && r.peak > 0.0;
    if (!out.converged && (atZero || atTop))
      throw CollectiveError("the reference's peak " + formatReal(c.target.peak) + " is out of reach of this spring-block scene: at sigma = " +
                          formatReal(b.sigma) + " its peak is " + formatReal(b.peak.mean) + ", the closest it gets");
  }
  // In physical units: d/d l_z = d/da / l_z0, d/d sigma = d/db / sigma_step.
  for (int i = 0; i < 2; ++i) {
    out.jacobian[i][0] = J[i][0] / lz0;
    out.jacobian[i][1] = J[i][1] / s.sigmaStep;
  }
  // The 95 % half-widths of the two measured quantities (SBM ensemble and reference fit), through
  // the inverse Jacobian, added in quadrature.
  const double slopeHalf = relativeSlopeHalfWidth(c, e);
  const double peakHalf = halfWidth(e.peak);
  const double (&P)[2][2] = out.jacobian;
  const double det = P[0][0] * P[1][1] - P[0][1] * P[1][0];
  if (std::fabs(det) > 0) {
    const double inv[2][2] = {{P[1][1] / det, -P[0][1] / det}, {-P[1][0] / det, P[0][0] / det}};
    out.layerError = std::hypot(inv[0][0] * slopeHalf, inv[0][1] * peakHalf);
    out.sigmaError = std::hypot(inv[1][0] * slopeHalf, inv[1][1] * peakHalf);
  }
  out.wallSeconds = MPI_Wtime() - wall0;
  return out;
}

}  // namespace gradfric::calibration
