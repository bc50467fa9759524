#pragma once
// Parameters of the 2D spring-block model (paper, "2D spring-block model"; docs/model.md).
// SI units throughout. All are PETSc options with the -sbm_ prefix, read by parameter_options.hpp;
// this header and its pure functions are part of the PETSc-free core.
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/pressure_response.hpp"
#include "gradfric/physics/random_surface.hpp"

#include <string>
#include <vector>

namespace gradfric::sbm {

enum class Integrator { RK4, VelocityVerlet };

struct Parameters {
  // The physical plate (-plate_ options, shared with the FEM). The lattice has Poisson's ratio
  // 1/3 (axial k, diagonal k/2); plate.thickness H is not used: the mass layer is l_z.
  Plate plate;
  double layerThickness = 5.7e-5;  // l_z [m]: block mass rho l_z l^2, slider K_s = G l^2 / l_z
  // The random surface (-surface_ options, shared with the FEM): the local friction's dispersion
  // around the plate's (graded) means, 2.8 % by default, over cells of side l_c; a block takes the
  // field averaged over its area. correlationLength 0: l_c = L/120 (surfaceOf()).
  SurfaceSettings surface = {0.028, 0.028, 0.0, 0.0, SurfaceKind::Cells, 0};
  // The friction law of every block (-friction_law, -friction_v_c): Coulomb, the paper's SBM, or
  // the paper's Eq. 1, the FEM's law (physics/friction_laws.hpp).
  FrictionLawSettings frictionLaw;
  // Lattice and numerics
  int blocksPerSide = 120;  // N_b
  double damping = 0.0;     // gamma [1/s]; default 0.1 sqrt(K_int/m)
  double timeStep = 0.0;    // dt [s]; default: defaultTimeStep()
  double automaticTimeStep = 0.0;  // what defaultTimeStep() gives, also when the user set dt
  // Defaults from the accuracy study (docs/accuracy.md): velocity Verlet at 0.03 of the slip time
  // keeps the time-integration error of mu_s below the statistical error of a 20-realisation
  // ensemble, at about a tenth of the cost of the paper's RK4 at 1e-8 s.
  Integrator integrator = Integrator::VelocityVerlet;
  double timeStepSafety = 0.25;  // default dt at most this fraction of the stability limit
  double timeStepSlip = 0.03;    // ... and at most this fraction of the slip time sqrt(m/K_s)
  // The one switch for work that cannot change the result (-sbm_skip_idle): jump over the quiet
  // phase before the first slip, bit for bit the stepped run. It relies on a load linear in time
  // and a constant normal force: turn it off for anything else.
  bool skipIdle = true;
  // Springs linearised about their rest direction (-sbm_spring small_strain): no square root,
  // F = k (e . du) e. Exact (large-rotation) springs by default; docs/accuracy.md has the study.
  bool smallStrain = false;
  // The load-dependent pressure p_i(t) = p_i^0 (1 + mu(t) g_i) (-pressure_response; none by
  // default: every block keeps its static normal force). It switches skipIdle off.
  PressureResponse pressureResponse;

  double spacing() const { return plate.length / blocksPerSide; }
  // The surface with its length resolved (L/120 where unset).
  SurfaceSettings surfaceOf() const {
    SurfaceSettings s = surface;
    if (s.correlationLength == 0.0) s.correlationLength = defaultCorrelationLength(plate.length);
    return s;
  }
  double blockMass() const { return plate.density * layerThickness * spacing() * spacing(); }
  double axialStiffness(double modulus) const { return 0.75 * modulus * layerThickness; }  // K_int
  double shearModulus(double modulus) const { return plate.shearModulus(modulus); }
  // Slider spring: shear stiffness of the column of height l_z under a block (docs/model.md).
  double sliderStiffness(double modulus) const {
    return shearModulus(modulus) * spacing() * spacing() / layerThickness;
  }
  double normalForcePerBlock() const { return plate.pressure * spacing() * spacing(); }
  // Loading time to the static threshold of the uniform plate: paper Eq. 2 with H -> l_z.
  double loadingTime() const { return plate.loadingTime(layerThickness); }
};

// What a run must determine (the shared friction measurement) and the spring-block run's own
// limits; it stops as soon as the observables are known.
struct Request {
  FrictionMeasurement measurement;    // -friction_ options: peak rule, kinetic window, history sampling
  std::vector<double> snapshotTimes;  // sigma_x/p maps at these times [s]
  double endTime = 0.0;               // if > 0: run exactly this long, whatever is known
  double maxTime = 0.0;               // give up (peak unconfirmed) after this long [s]
  int energyCheckInterval = 500;      // steps between two energy-balance checks (and at the end)
};

// The largest step that is stable for this lattice with the parameters' integrator (stiffest
// band, undamped): |omega_max dt| <= 2 sqrt(2) for RK4, 2 for velocity Verlet.
double stableTimeStep(const Parameters& parameters, const Grading& grading);

// The slip time 1/omega_s = sqrt(m / K_s) of the stiffest band: the time scale of a slip event,
// which sets the accuracy of mu_s and mu_k (stick/slip events make every scheme first order in
// dt, docs/accuracy.md). It does not depend on N_b.
double slipTime(const Parameters& parameters, const Grading& grading);

// Blocks finer than the surface's cells resolve it more finely: the slip-time bound of the step
// shrinks with the block, min(1, l / l_c), so a lattice ladder at a fixed surface refines space
// and time together and the verification's bar covers both (docs/verification.md). 1 for the
// blocks kind, where l_c is the block.
double surfaceStepFactor(const Parameters& parameters);

// The shipped default step: min(timeStepSafety x stable step, timeStepSlip x slip time x
// surfaceStepFactor).
double defaultTimeStep(const Parameters& parameters, const Grading& grading);

}  // namespace gradfric::sbm
