// -sbm_* options into Parameters and Request (PETSc library).
#include "gradfric/sbm/parameter_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/run_limits.hpp"
#include "gradfric/physics/field_options.hpp"
#include "gradfric/physics/friction_law_options.hpp"
#include "gradfric/physics/friction_options.hpp"
#include "gradfric/physics/stability.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/pressure_response_options.hpp"
#include "gradfric/physics/surface_options.hpp"
#include "gradfric/sbm/log_events.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::sbm {

Parameters readParameters(MPI_Comm comm, RunParameters* record, const Plate& plate, const Grading& grading) {
  installLogEvents();
  OptionReader o(comm, "sbm_", "Spring-block model", record);
  Parameters p;
  p.plate = plate;
  // The lattice's springs (axial k, diagonal k/2) fix Poisson's ratio at 1/3.
  if (std::fabs(plate.poissonRatio - 1.0 / 3.0) > 1e-12)
    throw InputError("-plate_nu", formatReal(plate.poissonRatio),
                     "1/3 with the spring-block model (its lattice has Poisson's ratio 1/3)");
  p.layerThickness = o.real("lz", p.layerThickness, "m",
                            "mass layer thickness l_z: block mass rho l_z l^2, slider K_s = G l^2/l_z (paper: 0.057 mm)");
  p.surface = readSurface(comm, record, plate, SurfaceDefaults{0.028, true});  // shared with the FEM
  p.frictionLaw = readFrictionLaw(o.comm(), record, p.frictionLaw, true, plate.thickness);  // shared with the FEM
  p.blocksPerSide = static_cast<int>(o.integer("N", p.blocksPerSide, 2, 4096, "1", "blocks per side N_b"));
  const std::string integrator = o.choice("integrator", "verlet", {"rk4", "verlet"},
                                          "time integrator, fixed step: classical RK4 (4 force evaluations a step) or velocity Verlet (1)");
  p.integrator = integrator == "verlet" ? Integrator::VelocityVerlet : Integrator::RK4;
  p.smallStrain = o.choice("spring", "exact", {"exact", "small_strain"},
                           "spring force: exact (k (|d| - l0) d/|d|) or small_strain (k (e.du) e, linearised about the "
                           "rest direction e: no square root; docs/accuracy.md)") == "small_strain";
  p.skipIdle = o.flag("skip_idle", p.skipIdle,
                      "skip work that cannot change the results: jump over the phase before the first slip, "
                      "and with Verlet update only tiles near moving blocks and not provably stuck "
                      "(bit for bit the stepped run; false: step every block from t = 0)");

  o.requirePositive("lz", p.layerThickness, "m");
  o.requireAtLeast("N", p.blocksPerSide, 2);
  if (p.blocksPerSide > 4096) throw InputError(o.fullName("N"), std::to_string(p.blocksPerSide), "2 <= N <= 4096");
  checkSpringBlockFields(grading, plate, p.blocksPerSide);  // the property fields at the block centres
  p.pressureResponse = readPressureResponse(comm, record, plate, p.blocksPerSide);  // -pressure_response

  const double kInt = p.axialStiffness(p.plate.youngsModulus);
  const double omega = std::sqrt(kInt / p.blockMass());
  if (auto gamma = o.realIfSet("gamma", "1/s", "damping coefficient gamma (underdamped: gamma < sqrt(K_int/m))",
                               "0.1 sqrt(K_int/m)")) {
    p.damping = *gamma;
    o.requireNonNegative("gamma", p.damping, "1/s");
  } else {
    p.damping = 0.1 * omega;
    o.recordDerived("gamma", p.damping, "1/s", "damping coefficient gamma = 0.1 sqrt(K_int/m)");
  }

  const double stable = stableTimeStep(p, grading);
  p.timeStepSafety = o.real("dt_safety", p.timeStepSafety, "1", "default dt: at most this fraction of the integrator's stability limit");
  o.requireRange("dt_safety", p.timeStepSafety, 1e-6, 1.0, "0 < dt_safety <= 1");
  p.timeStepSlip = o.real("dt_slip", p.timeStepSlip, "1", "default dt: at most this fraction of the slip time sqrt(m/K_s), times min(1, l/l_c) on blocks finer than the surface's cells");
  o.requirePositive("dt_slip", p.timeStepSlip, "");
  p.automaticTimeStep = defaultTimeStep(p, grading);
  const bool check = o.flag("dt_check", true, "refuse a dt above the stability limit (false: only to test the instability monitor)");
  const std::string scheme = p.integrator == Integrator::VelocityVerlet ? "velocity Verlet" : "RK4";
  const TimeStepPolicy policy{o.fullName("dt"), "the " + scheme + " stability limit of this lattice", stable, check};
  const auto requested = o.realIfSet("dt", "s", "time step (refused above the integrator's stability limit)",
                                     "min(dt_safety x stable step, dt_slip x slip time x min(1, l/l_c))");
  p.timeStep = policy.choose(requested, defaultTimeStep(p, grading));
  if (!requested)
    o.recordDerived("dt", p.timeStep, "s",
                    "time step = min(dt_safety x " + scheme + " stability limit " + formatReal(stable) +
                        " s, dt_slip x slip time " + formatReal(slipTime(p, grading)) + " s x min(1, l/l_c) " +
                        formatReal(surfaceStepFactor(p)) + ")");
  return p;
}

Request readRequest(MPI_Comm comm, RunParameters* record, const Parameters& p, const MeasurementDefaults& defaults) {
  Request q;
  q.measurement = readFrictionMeasurement(comm, record, p.loadingTime(), defaults);
  OptionReader o(comm, "sbm_", "Spring-block model", record);
  q.snapshotTimes = o.realList("snapshot_times", {}, "s", "times of the sigma_x/p snapshots (none: no stress computed)");
  for (double t : q.snapshotTimes) o.requireNonNegative("snapshot_times", t, "s");
  std::sort(q.snapshotTimes.begin(), q.snapshotTimes.end());
  const double load = p.loadingTime();
  if (auto t = o.realIfSet("t_max", "s", "give up if the peak is not confirmed by then", "20 t_load")) {
    q.maxTime = *t;
  } else {
    q.maxTime = 20.0 * load;
    o.recordDerived("t_max", q.maxTime, "s", "give up if the peak is not confirmed by then = 20 t_load");
  }
  q.endTime = o.real("t_end", 0.0, "s", "if > 0: run exactly this long, whatever the observables (0: stop when known)");
  o.requireNonNegative("t_end", q.endTime, "s");
  if (!(q.maxTime > 0)) throw InputError(o.fullName("t_max"), formatReal(q.maxTime), "> 0 [s]");
  // Before any work: a finite but absurd value (-sbm_dt 1e-300, a loading time of 1e300 s) would
  // otherwise run for ever.
  requireResolvedTimescale(record, load, p.timeStep, o.fullName("dt"), {"-sbm_", "-plate_", "-grading_"},
                           "loading time");
  const bool fixedLength = q.endTime > 0;
  requireRunLength(record, fixedLength ? q.endTime : q.maxTime, p.timeStep, p.automaticTimeStep, o.fullName("dt"),
                   {o.fullName(fixedLength ? "t_end" : "t_max")}, {"-sbm_", "-plate_", "-grading_"},
                   fixedLength ? "t_end" : "t_max");
  return q;
}

}  // namespace gradfric::sbm
