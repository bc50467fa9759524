#include "gradfric/fem/stable_step.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/core/run_limits.hpp"
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/mesh_sites.hpp"
#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/physics/stability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace gradfric::fem {

namespace {

// The largest local static coefficient of the contact: mu_s times the largest friction factor of
// the grading or field over the bottom faces, times the random surface's largest node factor when
// it is dispersed (the product of the two largest bounds every node's).
double largestStaticFriction(const FemParameters& q, const Grading& grading) {
  const MeshAxis x = meshAxisX(q), y = meshAxisY(q);
  const PropertySampler sampler = meshSampler(grading, x, y);
  double factor = 0;
  for (int j = 0; j < q.ny; ++j)
    for (int i = 0; i < q.nx; ++i) factor = std::max(factor, sampler.muStatic(x.unitCentre(i), y.unitCentre(j)));
  if (q.surface.sigmaStatic > 0) {
    const RandomSurface surface = femSurface(q.surface, q.plate.length, q.surfaceRealisation);
    double largestZ = -std::numeric_limits<double>::infinity();
    // Bands of rows of about 2^20 nodes: a bounded memory, and few queries (each one draws the
    // Gaussian field's noise over its band).
    const int rows = std::max(1, (1 << 20) / (q.nx + 1));
    for (int j = 0; j <= q.ny; j += rows)
      for (const SurfaceDeviations& z : tributarySurface(surface, x, y, 0, q.nx, j, std::min(j + rows - 1, q.ny)))
        largestZ = std::max(largestZ, z.zStatic);
    factor *= surfaceCoefficients(1.0, 1.0, 1.0, q.surface, SurfaceDeviations{largestZ, 0.0, 0.0}).muStatic;
  }
  return q.plate.muStatic * factor;
}

// The highest squared element frequency of an edge-graded mesh: each cell shape (a width class
// along x and one along y) with the stiffest E among its cells; the smallest cells at the edges
// usually decide, but a stiff band inside can.
double gradedElementFrequencySquared(const FemParameters& q, const Grading& grading) {
  const MeshAxis x = meshAxisX(q), y = meshAxisY(q);
  const PropertySampler sampler = meshSampler(grading, x, y);
  const std::size_t classesY = y.classWidth.size();
  std::vector<double> factor(x.classWidth.size() * classesY, 0.0);
  for (int j = 0; j < q.ny; ++j)
    for (int i = 0; i < q.nx; ++i) {
      double& f = factor[x.widthClass[i] * classesY + y.widthClass[j]];
      f = std::max(f, sampler.modulus(x.unitCentre(i), y.unitCentre(j)));
    }
  double omega2 = 0;
  for (std::size_t cx = 0; cx < x.classWidth.size(); ++cx)
    for (std::size_t cy = 0; cy < classesY; ++cy) {
      const BoxElement element = makeBoxElement(x.classWidth[cx], y.classWidth[cy], q.plate.thickness / q.nz,
                                                q.plate.poissonRatio, q.element);
      const double e = q.plate.youngsModulus * factor[cx * classesY + cy];
      omega2 = std::max(omega2, elementMaxFrequencySquared(element, e, q.plate.density));
    }
  return omega2;
}

// frictionCoupling: the factor on the normal penalty spring (1: the springs alone).
double stableStep(const FemParameters& q, const Grading& grading, double frictionCoupling) {
  const BoxElement element = makeBoxElement(q.plate.length / q.nx, q.plate.length / q.ny, q.plate.thickness / q.nz,
                                            q.plate.poissonRatio, q.element);
  double factor = 1.0;
  for (int band = 0; band < grading.bands; ++band)
    if (grading.gradesModulus()) factor = std::max(factor, grading.bandFactor(band));
  if (grading.fields && grading.fields->modulus) {  // an E field: its stiffest cell
    const PropertySampler sampler(grading, q.nx, q.ny);
    for (int j = 0; j < q.ny; ++j)
      for (int i = 0; i < q.nx; ++i) factor = std::max(factor, sampler.modulus((i + 0.5) / q.nx, (j + 0.5) / q.ny));
  }
  const double elementOmega2 = q.edge.uniform()
                                   ? elementMaxFrequencySquared(element, q.plate.youngsModulus * factor, q.plate.density)
                                   : gradedElementFrequencySquared(q, grading);
  double omega2 = elementOmega2;
  // Penalty springs: k * area / nodal mass = 2 k / (rho hz) at every bottom node (on a graded mesh
  // too: a node's area and mass both sum the same in-plane cell areas).
  // Kinematic contact adds no spring: the element alone sets the step.
  if (q.contact && q.contactMethod == ContactMethod::Penalty)
    omega2 += 2.0 * std::max(q.kn * frictionCoupling, q.kt) / (q.plate.density * element.hz);
  const double omega = std::sqrt(omega2);
  // The damping switched on at the peak (towards the slider) adds to -fem_slide_damping.
  const double gamma = std::max(q.settleDamping, q.slideDamping + std::max(q.peakDamping, 0.0));
  // Linear bulk viscosity: b1 is the damping ratio of the highest (dilatational) mode (Abaqus).
  // Stiffness-proportional damping acts on the element's stiffness, not on the penalty springs:
  // damping ratio beta omega_e^2 / (2 omega) of the combined mode.
  const double xi = 0.5 * (q.stiffnessDamping + q.peakStiffnessDamping) * elementOmega2 / omega + gamma / (2.0 * omega) + q.bulkLinear;
  return centralDifferenceStableStep(omega2, xi);
}

}  // namespace

double stableTimeStep(const FemParameters& q, const Grading& grading) { return stableStep(q, grading, 1.0); }

// A sliding node's friction force mu p = mu k_n (-u_z) ties its tangential force to its normal
// displacement: per node the penalty stiffness becomes [[0, mu k_n], [0, k_n]] (tangential,
// normal), not symmetric, of norm k_n sqrt(1 + mu^2), which bounds its share of the highest
// frequency where k_n alone does not. Measured (input/fem_fig2_H050_coarse.opts, Coulomb and
// Eq. 1 laws, which slide at mu_s): 0.99 of the springs-alone step blew up while sliding.
double largestTimeStep(const FemParameters& q, const Grading& grading) {
  const double mu = largestStaticFriction(q, grading);
  return stableStep(q, grading, std::sqrt(1.0 + mu * mu));
}

double chooseTimeStep(const FemParameters& q, const Grading& grading) {
  const double stable = stableTimeStep(q, grading), largest = largestTimeStep(q, grading);
  const TimeStepPolicy policy{
      "-fem_dt", "the stable step with friction's coupling (mesh, wave speed, penalty springs, friction, damping)",
      largest, q.dtCheck};
  // (An absurd mu_s, say 1e300, makes the coupled limit 0: the plate's own check names it later.)
  if (!q.dt && q.dtCheck && largest > 0 && q.dtSafety * stable > largest)
    throw InputError("-fem_dt_safety", formatReal(q.dtSafety),
                     "<= " + formatReal(largest / stable) + " here: dt_safety x the stable step " + formatReal(stable) +
                         " s must stay within the stable step with friction's coupling, " + formatReal(largest) + " s");
  return policy.choose(q.dt, q.dtSafety * stable);
}

void requireFemRunLength(const FemParameters& q, const Grading& grading, const RunParameters* record) {
  const double duration = q.rampTime + q.settleTime + q.slideTime;
  const double dt = chooseTimeStep(q, grading);  // once: the friction bound draws the surface
  requireResolvedTimescale(record, q.eq2PeakTime(), dt, "-fem_dt", {"-fem_", "-plate_", "-grading_"}, "Eq. 2 peak time");
  requireRunLength(record, duration, dt, q.dtSafety * stableTimeStep(q, grading), "-fem_dt",
                   {"-fem_slide_time", "-fem_settle_time", "-fem_ramp_time"}, {"-fem_", "-plate_", "-grading_"},
                   "pressure step + sliding");
}

}  // namespace gradfric::fem
