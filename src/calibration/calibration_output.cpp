// The report and the files of a calibration (include/gradfric/calibration/calibration.hpp).
#include "gradfric/calibration/calibration.hpp"

#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"

#include <petscsys.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace gradfric::calibration {

namespace {

double halfWidth(const campaign::Summary& s) { return s.ciHalfWidth(); }

// Each comma-separated path made absolute (from the working directory the run resolved it in).
std::string absolutePaths(const std::string& value) {
  std::string out;
  size_t start = 0;
  for (size_t comma = 0; comma != std::string::npos; start = comma + 1) {
    comma = value.find(',', start);
    const std::string item = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out += (start ? "," : "") + (item.empty() ? item : std::filesystem::absolute(item).lexically_normal().string());
  }
  return out;
}

// Root mean square of the mean SBM curve against the reference, up to the reference's peak.
double curveResidual(const Calibration& c, const Evaluation& e, int* samples) {
  const std::vector<double> reference = interpolate(c.reference.time, c.reference.mu, c.grid);
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < c.grid.size(); ++k) {
    if (c.grid[k] > c.target.peakTime || !std::isfinite(e.meanCurve[k]) || !std::isfinite(reference[k])) continue;
    sum += (e.meanCurve[k] - reference[k]) * (e.meanCurve[k] - reference[k]);
    ++n;
  }
  *samples = n;
  return n > 0 ? std::sqrt(sum / n) : NAN;
}

void writeScene(const std::string& work, const std::string& path, const Calibration& c, const CalibrationResult& r) {
  std::ofstream out(work);
  const Evaluation& e = r.fitted();
  char line[512];
  const bool layer = c.settings.fit == Fit::Layer;
  out << "# gradfric-calibrate: spring-block " << (layer ? "l_z fitted (sigma the surface's)" : "l_z and sigma fitted")
      << " to " << c.settings.source.path << " (" << c.reference.kind << ")\n";
  std::snprintf(line, sizeof line,
                "# reference: loading slope %.6e 1/s (over %.2g-%.2g mu_s), peak mu_s %.6f\n", c.target.slope,
                c.scene.window.low, c.scene.window.high, c.target.peak);
  out << line;
  if (layer)
    std::snprintf(line, sizeof line,
                  "# fitted:    l_z = %.6e +- %.2e m (95 %%); surface sigma_s %.6g, sigma_k %.6g\n"
                  "# residuals: slope %+.4f %%; peak %+.6f (not fitted; ensemble 95 %% CI +- %.6f); converged after %zu evaluations\n",
                  e.layerThickness, r.layerError, e.sigma, e.sigmaKinetic, 100 * (e.slope.mean / c.target.slope - 1),
                  e.peak.mean - c.target.peak, halfWidth(e.peak), r.evaluations.size());
  else
    std::snprintf(line, sizeof line,
                  "# fitted:    l_z = %.6e +- %.2e m, sigma = %.6f +- %.6f (95 %%)\n"
                  "# residuals: slope %+.4f %%, peak %+.6f (ensemble 95 %% CI +- %.6f); converged after %zu evaluations\n",
                  e.layerThickness, r.layerError, e.sigma, r.sigmaError, 100 * (e.slope.mean / c.target.slope - 1),
                  e.peak.mean - c.target.peak, halfWidth(e.peak), r.evaluations.size());
  out << line;
  out << "# gradfric -options_file " << path << " -output run.h5 reproduces the fitted ensemble (same seed)\n";
  // A file to read is written absolute: in a scene file it would be read from the scene's folder.
  for (const auto& o : c.sceneOptions) out << o.name << " " << (o.path ? absolutePaths(o.value) : o.value) << "\n";
  std::snprintf(line, sizeof line, "-sbm_lz %.10g\n-surface_sigma_s %.10g\n-surface_sigma_k %.10g\n", e.layerThickness, e.sigma,
                e.sigmaKinetic);
  out << line << "-ensemble_realisations " << c.scene.realisations << "\n-ensemble_seed " << c.scene.seed << "\n";
  if (!out.flush()) throw std::runtime_error("cannot write " + work);
}

void writeCurves(const std::string& path, const Calibration& c, const Evaluation& e) {
  std::ofstream out(path);
  const std::vector<double> reference = interpolate(c.reference.time, c.reference.mu, c.grid);
  out << "t,mu_reference,mu_sbm_mean\n";
  char line[128];
  for (std::size_t k = 0; k < c.grid.size(); ++k) {
    std::snprintf(line, sizeof line, "%.9e,%.9g,%.9g\n", c.grid[k], reference[k], e.meanCurve[k]);
    out << line;
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
}

}  // namespace

void writeCalibration(MPI_Comm comm, const Calibration& c, const CalibrationResult& r) {
  const Evaluation& e = r.fitted();
  int samples = 0;
  const double rms = curveResidual(c, e, &samples);
  const double paperLayer = 5.7e-5, paperSigma = 0.028;
  // The peak's l_z derivative is measured only if l_z moved (it does not when the first guess,
  // from the slope, already fits it).
  double lowest = e.layerThickness, highest = e.layerThickness;
  for (const auto& x : r.evaluations) {
    lowest = std::min(lowest, x.layerThickness);
    highest = std::max(highest, x.layerThickness);
  }
  char text[96] = "";
  if (highest > lowest * 1.001) std::snprintf(text, sizeof text, ", d(peak)/d l_z = %.4e 1/m", r.jacobian[1][0]);
  const std::string coupling = text;
  const bool layer = c.settings.fit == Fit::Layer;
  const double peakResidual = e.peak.mean - c.target.peak;
  const char* inside = std::fabs(peakResidual) <= halfWidth(e.peak) ? "inside" : "outside";
  GF_CALL(PetscPrintf(comm,
                      "Calibration %s after %zu evaluation(s) (%ld realisations, %.2f s wall):\n"
                      "  l_z   = %.6e m +- %.2e m (95 %%)   [paper: %.3g m, %+.1f %%]\n",
                      r.converged ? "converged" : "did NOT converge (best evaluation reported)", r.evaluations.size(),
                      r.realisations, r.wallSeconds, e.layerThickness, r.layerError, paperLayer,
                      100 * (e.layerThickness / paperLayer - 1)));
  if (layer)
    GF_CALL(PetscPrintf(comm, "  sigma_s = %.6f, sigma_k = %.6f: the surface's (-surface_sigma_s/_k), not fitted\n", e.sigma,
                        e.sigmaKinetic));
  else
    GF_CALL(PetscPrintf(comm, "  sigma = %.6f +- %.6f (95 %%)       [paper: %.3g, %+.1f %%]\n", e.sigma, r.sigmaError,
                        paperSigma, 100 * (e.sigma / paperSigma - 1)));
  GF_CALL(PetscPrintf(
      comm,
      "  slope: SBM %.6e +- %.2e 1/s, reference %.6e +- %.2e 1/s (95 %%): residual %+.4f %%\n"
      "  peak:  SBM %.6f +- %.6f (95 %% CI), reference %.6f: residual %+.6f (%+.2f %%, %s the CI)%s\n"
      "  mean mu(t) - reference up to the peak: RMS %.6f over %d samples\n",
      e.slope.mean, halfWidth(e.slope), c.target.slope,
      (std::isfinite(c.target.slopeHalfWidth) ? c.target.slopeHalfWidth : 0.0), 100 * (e.slope.mean / c.target.slope - 1),
      e.peak.mean, halfWidth(e.peak), c.target.peak, peakResidual, 100 * peakResidual / c.target.peak, inside,
      layer ? ": what the two models differ by on this surface (not fitted)" : "", rms, samples));
  if (layer)
    GF_CALL(PetscPrintf(comm, "  d(slope ratio)/d l_z = %.4e 1/m (%s)%s\n", r.jacobian[0][0],
                        r.evaluations.size() > 1 ? "secant" : "the 1/l_z law", coupling.c_str()));
  else
    GF_CALL(PetscPrintf(comm, "  d(slope ratio)/d l_z = %.4e 1/m, d(peak)/d sigma = %.4f (secant)%s\n", r.jacobian[0][0],
                        r.jacobian[1][1], coupling.c_str()));
  if (!r.converged)  // a scene that does not reproduce the reference is not written
    throw CollectiveError("the calibration did not converge in " + std::to_string(r.evaluations.size()) +
                          " evaluations (-calibrate_max_evaluations; the best is printed above): nothing written");
  c.scenePlan.writeOnRank0(comm, [&](const std::string& work) { writeScene(work, c.scenePlan.path(), c, r); });
  if (c.curvePlan) c.curvePlan->writeOnRank0(comm, [&](const std::string& work) { writeCurves(work, c, e); });
  c.scenePlan.commit(comm);
  if (c.curvePlan) c.curvePlan->commit(comm);
  GF_CALL(PetscPrintf(comm, "Scene written to %s%s%s\n", c.scenePlan.path().c_str(), c.curvePlan ? ", curves to " : "",
                      c.curvePlan ? c.curvePlan->path().c_str() : ""));
}

}  // namespace gradfric::calibration
