#include "gradfric/fem/parameter_options.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/fem/term_registry.hpp"
#include "gradfric/physics/friction_law_options.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/friction_options.hpp"
#include "gradfric/physics/surface_options.hpp"

#include <string>

namespace gradfric::fem {

// The edge grading's values, and nx, ny multiples of its unit (edge_grading.hpp).
static void requireEdgeGrading(const OptionReader& o, const FemParameters& q) {
  const double ratio = q.edge.ratio, L = q.plate.length;
  if (!(ratio == 1.0 || (ratio >= kEdgeRatioMin && ratio <= kEdgeRatioMax)))
    throw InputError(o.fullName("edge_ratio"), formatReal(ratio),
                     "1 (uniform) or " + formatReal(kEdgeRatioMin) + " <= ratio <= " + formatReal(kEdgeRatioMax));
  if (o.wasSet("edge_band")) {
    const int bands = refinedBandsOf(q.edge.band, L);
    if (!(q.edge.band > 0) || bands < 1 || bands > kEdgeBandsMax)
      throw InputError(o.fullName("edge_band"), formatReal(q.edge.band),
                       "k L/10 [m] with k = 1.." + std::to_string(kEdgeBandsMax) + " (L/10 = " + formatReal(L / kGradingBands) +
                           " m: the grading bands' boundaries stay on element faces)");
  }
  if (q.edge.uniform()) return;
  const EdgeMap map(ratio, refinedBandsOf(q.edge.band, L));
  for (const char* name : {"nx", "ny"}) {
    const int n = name[1] == 'x' ? q.nx : q.ny;
    if (n % map.cellsPerUnit() != 0)
      throw InputError(o.fullName(name), std::to_string(n),
                       "a multiple of " + std::to_string(map.cellsPerUnit()) + " with -fem_edge_ratio " + formatReal(ratio) +
                           " (the cells of one unit of this grading: every band holds whole cells)");
  }
}

FemParameters readFemParameters(MPI_Comm comm, RunParameters* record, const Plate& plate) {
  // One sampling rule for the stored mu(t), a single run's and a sweep's: the friction observer's.
  // The normal-stress memory is part of the friction law, its length in units of D_c.
  refuseRetiredOption("-fem_pc_length",
                      "replaced by -friction_memory_length, the friction law's normal-stress memory, in units of "
                      "D_c (1e-7 m at the default D_c 2.5e-8 m is -friction_memory_length 4)");
  refuseRenamedOption("-fem_pc_speed", "-friction_memory_speed", "the normal-stress memory belongs to the friction law");
  refuseRetiredOption("-fem_history_every",
                      "removed: the stored mu(t) is the friction observer's history, as in a FEM sweep; its sampling "
                      "is -friction_history_interval <seconds> (default t_load / 1000)");
  OptionReader o(comm, "fem_", "Finite-element plate model (3D, explicit)", record);
  FemParameters q(plate);  // the defaults, derived ones included; the options override them
  q.nx = static_cast<int>(o.integer("nx", q.nx, 1, 100000, "1", "hexahedra along x (grading axis)"));
  q.ny = static_cast<int>(o.integer("ny", q.ny, 1, 100000, "1", "hexahedra along y"));
  q.nz = static_cast<int>(o.integer("nz", q.nz, 1, 100000, "1", "hexahedra through the thickness"));
  q.edge.ratio = o.real("edge_ratio", q.edge.ratio, "1",
                        "in-plane mesh graded toward the edges: interior element size / edge element size (1: uniform; "
                        "else 1.1 to 16, the cells shrinking smoothly across the edge bands, nx and ny multiples of the "
                        "grading's unit, which is printed; docs/fem.md)");
  if (auto band = o.realIfSet("edge_band", "m",
                              "width of the refined band at each edge with -fem_edge_ratio: k L/10, k = 1..4 (the "
                              "grading bands' boundaries stay on element faces)",
                              "L/10"))
    q.edge.band = *band;
  q.element = o.choice("element", elementTypeName(q.element), {"q1", "q1i"},
                       "hexahedron: q1 trilinear, q1i with incompatible bending modes (C3D8I-like, condensed)") == "q1"
                  ? ElementType::Trilinear
                  : ElementType::IncompatibleModes;
  q.blockedKernel = o.choice("kernel", q.blockedKernel ? "blocked" : "dense", {"dense", "blocked"},
                             "elastic cell kernel: blocked in the cell's mirror basis (0.58 x the dense time), or the "
                             "dense 24x24 product (the reference; equal to round-off)") == "blocked";
  q.staticPressureStep =
      o.choice("pressure_step", q.staticPressureStep ? "static" : "dynamic", {"static", "dynamic"},
               "step 1: static (the pressed equilibrium solved by CG, then sliding from rest; penalty contact, "
               "else dynamic) or dynamic (pressure ramp and hold in time)") == "static";
  q.frictionLaw = readFrictionLaw(comm, record, q.frictionLaw, true, plate.thickness, true);  // shared with the SBM
  // The SBM's surface with the paper's 3D default, no dispersion (then nothing is drawn); no
  // blocks kind: a node has no block of its own.
  q.surface = readSurface(comm, record, plate, SurfaceDefaults{0.0, false});
  const PetscInt seed = o.integer("seed", 1, 0, PETSC_MAX_INT, "1", "seed of the random surface: a single run takes its realisation 0, realisation r of an ensemble (-ensemble_realisations) its realisation r");
  o.requireAtLeast("seed", seed, 0);
  q.surface.seed = static_cast<std::uint64_t>(seed);
  q.slipLength = o.real("slip_length", q.slipLength, "m",
                        "with -friction_law exponential or coulomb: slip length of the friction memory, a node's "
                        "strength follows the law's value over this slip (-fem_slip_evolution); 0: the law alone");
  q.slipHealingOnly = o.choice("slip_evolution", q.slipHealingOnly ? "healing" : "slip", {"slip", "healing"},
                               "how the slip state follows Eq. 1: slip (Ruina's slip law, weakening and healing over "
                               "D_c) or healing (weakening at once as Eq. 1, only the healing over D_c)") == "healing";
  const std::string contact =
      o.choice("contact", "penalty", {"penalty", "kinematic", "none"},
               "contact with the rigid plane: penalty springs, kinematic (exact, predictor-corrector; gfverlet only), "
               "none (free bottom face, for tests)");
  q.contact = contact != "none";
  q.contactMethod = contact == "kinematic" ? ContactMethod::Kinematic : ContactMethod::Penalty;
  if (auto kn = o.realIfSet("kn", "Pa/m", "normal penalty stiffness k_n", "250 G/H")) q.kn = *kn;
  q.kt = o.realIfSet("kt", "Pa/m", "tangential penalty stiffness k_t", "k_n").value_or(q.kn);
  readFemTermOptions(o, q);  // the optional terms' own options (src/fem/terms/)
  if (auto g = o.realIfSet("settle_damping", "1/s", "mass-proportional damping during the pressure step", "c_s/H"))
    q.settleDamping = *g;
  q.bulkLinear = o.real("bulk_b1", q.bulkLinear, "1",
                        "linear bulk viscosity b1 (0.06 with -fem_bulk_viscosity, as Abaqus/Explicit; 0: off)");
  q.bulkQuadratic = o.real("bulk_b2", q.bulkQuadratic, "1",
                           "quadratic bulk viscosity b2, in compression (1.2 with -fem_bulk_viscosity; 0: off)");
  q.slideDamping = o.real("slide_damping", 0.0, "1/s", "mass-proportional damping during sliding");
  q.stiffnessDamping = o.real("stiffness_damping", 0.0, "s",
                              "stiffness-proportional (Rayleigh beta) damping (0.2 H/(pi c_p): steady sliding, see "
                              "docs/accuracy_fem.md)");
  if (auto g = o.realIfSet("peak_damping", "1/s",
                           "mass-proportional damping towards the slider's velocity, from the confirmed peak on (0: off)",
                           "c_s/H (1/pi of critical in the thickness-shear mode)"))
    q.peakDamping = *g;
  q.peakStiffnessDamping = o.real("peak_stiffness_damping", 0.0, "s",
                                  "stiffness-proportional damping from the confirmed peak on (0: off)");
  {
    const std::string start = o.choice("peak_damping_start", "confirmed", {"confirmed", "drop", "sliding"},
                                       "when the damping of the sliding plate starts: the confirmed peak, the first drop "
                                       "of mu below its maximum, or the start of sliding (study only: it then damps the peak)");
    q.peakDampingStart = start == "confirmed" ? FemParameters::DampingStart::Confirmed
                         : start == "drop"    ? FemParameters::DampingStart::Drop
                                              : FemParameters::DampingStart::Sliding;
  }
  if (o.flag("bulk_viscosity", false, "bulk viscosity of Abaqus/Explicit (-fem_bulk_b1, -fem_bulk_b2)")) {
    q.bulkLinear = 0.06;
    q.bulkQuadratic = 1.2;
  }
  q.dt = o.realIfSet("dt", "s", "time step", "dt_safety * stable step");
  q.dtSafety = o.real("dt_safety", q.dtSafety, "1", "time step as a fraction of the stable step");
  q.dtCheck = o.flag("dt_check", true,
                     "refuse a -fem_dt above the stable step (false: TESTING ONLY, to exercise the blow-up monitor)");
  q.monitorEvery = static_cast<int>(
      o.integer("monitor_every", q.monitorEvery, 1, 1000000000, "1", "blow-up monitor: energy and finiteness check every n steps"));
  q.monitorFactor = o.real("monitor_factor", q.monitorFactor, "1",
                           "blow-up monitor: stop when kinetic + elastic energy exceeds this x (energy put in + p^2 L^2 H / 2E)");
  if (auto t = o.realIfSet("ramp_time", "s", "pressure ramp duration", "20 H/c_s")) q.rampTime = *t;
  if (auto t = o.realIfSet("settle_time", "s", "hold under pressure before sliding", "10 H/c_s")) q.settleTime = *t;
  if (auto t = o.realIfSet("slide_time", "s", "longest sliding duration",
                              "1.5 t_load + the latest mu_k window's end (Eq. 2 t_load); at least 9 t_load with -friction_memory_length")) q.slideTime = *t;
  q.stopWhenKnown = o.flag("stop_when_known", true, "stop once the -friction_observables are known");
  q.partitioner = o.choice("partitioner", q.partitioner, {"metis", "ptscotch", "simple"}, "mesh partitioner");
  q.snapshotTimes = o.realList("snapshot_times", {}, "s", "field snapshot times after the start of sliding");
  q.verbose = o.flag("verbose", true, "print progress");

  o.requireAtLeast("nx", q.nx, 1);
  o.requireAtLeast("ny", q.ny, 1);
  o.requireAtLeast("nz", q.nz, 1);
  requireEdgeGrading(o, q);
  if (isStateLaw(q.frictionLaw)) {  // the slip length (-fem_slip_length) belongs to the stateless laws
    const char* allowed = "only with -friction_law exponential or coulomb (the state law's length is -friction_d_c)";
    if (o.wasSet("slip_length")) throw InputError(o.fullName("slip_length"), formatReal(q.slipLength), allowed);
    if (o.wasSet("slip_evolution"))
      throw InputError(o.fullName("slip_evolution"), q.slipHealingOnly ? "healing" : "slip", allowed);
  }
  o.requireNonNegative("slip_length", q.slipLength, "m");
  if (o.wasSet("slip_length"))  // the default is not checked against H: a bad -plate_H is refused by its own name
    o.requireRange("slip_length", q.slipLength, 0.0, q.plate.thickness, "0 <= D_c <= H (the plate's thickness)");
  if (q.frictionLaw.memoryLength > 0 && !q.contact)
    throw InputError("-friction_memory_length", formatReal(q.frictionLaw.memoryLength), "0 with -fem_contact none");
  if (o.wasSet("kn")) o.requirePositive("kn", q.kn, "Pa/m");
  if (o.wasSet("kt")) o.requirePositive("kt", q.kt, "Pa/m");
  if (o.wasSet("settle_damping")) o.requireNonNegative("settle_damping", q.settleDamping, "1/s");
  o.requireRange("bulk_b1", q.bulkLinear, 0.0, 1.0, "0 <= b1 <= 1");
  o.requireRange("bulk_b2", q.bulkQuadratic, 0.0, 10.0, "0 <= b2 <= 10");
  o.requireNonNegative("slide_damping", q.slideDamping, "1/s");
  o.requireNonNegative("stiffness_damping", q.stiffnessDamping, "s");
  if (o.wasSet("peak_damping")) o.requireNonNegative("peak_damping", q.peakDamping, "1/s");
  o.requireNonNegative("peak_stiffness_damping", q.peakStiffnessDamping, "s");
  if (q.dt) o.requirePositive("dt", *q.dt, "s");
  o.requireRange("dt_safety", q.dtSafety, 1e-6, 1.0, "0 < dt_safety <= 1");
  for (const char* name : {"ramp_time", "settle_time"})
    if (o.wasSet(name)) o.requireNonNegative(name, name[0] == 'r' ? q.rampTime : q.settleTime, "s");
  if (o.wasSet("slide_time")) o.requirePositive("slide_time", q.slideTime, "s");
  // Memory before any work: a hexahedron costs a few kB (DMPlex, state, element data).
  const double cells = static_cast<double>(q.nx) * q.ny * q.nz;
  if (cells > 2e7) {
    const char* largest = q.nx >= q.ny && q.nx >= q.nz ? "nx" : q.ny >= q.nz ? "ny" : "nz";
    const int value = largest[1] == 'x' ? q.nx : largest[1] == 'y' ? q.ny : q.nz;
    throw InputError(o.fullName(largest), std::to_string(value),
                     "a mesh of at most 2e7 hexahedra (nx ny nz = " + formatReal(cells) + ")");
  }
  o.requireAtLeast("monitor_every", q.monitorEvery, 1);
  o.requireRange("monitor_factor", q.monitorFactor, 1.0, 1e300, ">= 1");

  // The shared friction measurement, its times derived from the FEM's loading time (Eq. 2 with H)
  // and the FEM's steady mu_k window (docs/accuracy_fem.md, "The defaults and why"),
  // then the sliding time that fits its window.
  q.measurement = readFrictionMeasurement(comm, record, q.eq2PeakTime(),
                                          MeasurementDefaults{kMukSteadyTolerance, kMukLatestDelay});
  if (!o.wasSet("slide_time"))
    q.slideTime = defaultSlideTime(q.eq2PeakTime(), q.measurement, q.frictionLaw.memoryLength > 0);
  if (!o.wasSet("kn")) o.recordDerived("kn", q.kn, "Pa/m", "normal penalty stiffness k_n");
  if (!o.wasSet("kt")) o.recordDerived("kt", q.kt, "Pa/m", "tangential penalty stiffness k_t");
  if (!o.wasSet("settle_damping"))
    o.recordDerived("settle_damping", q.settleDamping, "1/s", "mass-proportional damping during the pressure step");
  if (!o.wasSet("peak_damping"))
    o.recordDerived("peak_damping", q.peakDamping, "1/s", "damping towards the slider from the confirmed peak on");
  if (!o.wasSet("ramp_time")) o.recordDerived("ramp_time", q.rampTime, "s", "pressure ramp duration");
  if (!o.wasSet("settle_time")) o.recordDerived("settle_time", q.settleTime, "s", "hold under pressure");
  if (!o.wasSet("edge_band")) o.recordDerived("edge_band", q.edge.band, "m", "width of the refined band at each edge");
  if (!o.wasSet("slide_time")) o.recordDerived("slide_time", q.slideTime, "s", "longest sliding duration");
  return q;
}

}  // namespace gradfric::fem
