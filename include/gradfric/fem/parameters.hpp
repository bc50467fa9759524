#pragma once
// Parameters of the 3D finite-element plate model (all -fem_ options). PETSc-free (in the core);
// their reader is parameter_options.hpp.
#include "gradfric/fem/edge_grading.hpp"
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/term_settings.hpp"
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/friction_laws_settings.hpp"
#include "gradfric/physics/plate.hpp"
#include "gradfric/physics/random_surface.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gradfric::fem {

// The FEM's steady mu_k window (docs/accuracy_fem.md, "The defaults and why"): the window
// (0.5-1.5 t_load after the peak at first) slides on until its quarters' means agree within this
// fraction, starting at most kMukLatestDelay t_load after the peak.
constexpr double kMukSteadyTolerance = 0.002;
constexpr double kMukLatestDelay = 4.0;

// How the bottom face meets the rigid plane (-fem_contact): penalty springs (the paper's and the
// default), exact predictor-corrector contact (kinematic, the reference), or none (free face).
enum class ContactMethod { Penalty, Kinematic };
const char* contactMethodName(ContactMethod method);

// The parameters come in groups, as the spring-block model's (sbm::Parameters and sbm::Request):
// FemParameters derives from each, so a function can take only the group it needs. Every value is
// final: the defaults derived from the plate (penalties, damping, ramp and hold, the edge band,
// the measurement's times, the sliding time) are computed once, by the FemParameters(plate)
// constructor or the reader, never later by the library. kNotDerived marks the derived members
// of a group built alone (NaN: it fails every comparison instead of passing for a value).
constexpr double kNotDerived = std::numeric_limits<double>::quiet_NaN();

// The mesh: box, edge grading, element, cell kernel, partition.
struct FemMesh {
  int nx = 100, ny = 100, nz = 10;  // nz 10: the 3D ladder bounds mu_s there (docs/accuracy_fem.md)
  // -fem_edge_ratio, -fem_edge_band: in-plane cells shrinking toward the edges (edge_grading.hpp;
  // ratio 1, the default: the uniform mesh). The band defaults to L/10.
  EdgeGrading edge;
  ElementType element = ElementType::Trilinear;  // -fem_element q1 | q1i (docs/fem.md)
  bool blockedKernel = true;  // -fem_kernel blocked | dense (mirror-basis kernel, docs/accuracy_fem.md, "Cost")
  std::string partitioner = "metis";
};

// The contact with the rigid plane and its friction.
struct FemContact {
  // Friction law of the contact nodes (-friction_law, shared with the spring-block model): by
  // default the state law (physics/state_weakening_law.hpp), Eq. 1 as its steady state with the
  // weakening length D_c that makes mu_s converge under refinement (docs/accuracy_fem.md, "The
  // friction law"); exponential is Eq. 1 itself, coulomb the SBM's law.
  FrictionLawSettings frictionLaw = {"state", FrictionLawSettings::kCriticalVelocity, FrictionLawSettings::kSlipLength};
  // With a stateless law (exponential, coulomb): the friction memory, a slip length over which a
  // node's strength follows the law (physics/slip_state_law.hpp). By default (healing) a node's
  // strength drops with its slip rate at once as Eq. 1 says, but regains mu_s as it slows down
  // only over a slip D_c, so a node that stops keeps its kinetic strength: this ends Eq. 1's
  // node-scale stick-slip after the peak; slip: Ruina's slip law, weakening over D_c too. 0: the
  // law alone, a stopped node back at mu_s. Neither gives Eq. 1 a length that converges mu_s
  // under refinement: the state law does (docs/accuracy_fem.md, "The friction law").
  double slipLength = 1e-8;
  bool slipHealingOnly = true;  // -fem_slip_evolution healing (true) | slip
  bool contact = true;   // false: free bottom face (-fem_contact none, testing)
  ContactMethod contactMethod = ContactMethod::Penalty;
  // Penalty stiffnesses [Pa/m], by default penaltyFactor G/H (docs/accuracy_fem.md, "The defaults and why"):
  // the tangential springs add the compliance 1/(k_t L^2) to the plate's shear compliance
  // H/(G L^2), so the loading slope carries -G/(H k_t); 250 G/H keeps it at 0.4 %. k_t: k_n.
  double kn = kNotDerived, kt = kNotDerived;
  static constexpr double penaltyFactor = 250.0;
  // The random surface (-surface_ options, shared with the spring-block model) on the local mu_s,
  // mu_k: each bottom node takes realisation surfaceRealisation of seed -fem_seed averaged over
  // its tributary rectangle (plate_properties.hpp). No dispersion by default: the paper's
  // deterministic 3D model. The constructor sets l_c = L/120 and the seed 1. A single run is
  // realisation 0; a sweep's realisation r (-ensemble_realisations) is r.
  SurfaceSettings surface;
  std::uint32_t surfaceRealisation = 0;
};

// Damping: bulk viscosity, mass- and stiffness-proportional, in each phase.
struct FemDamping {
  // Bulk viscosity (Abaqus/Explicit's form, bulk_viscosity.hpp): pressure b1 rho c_d L_e eps_v'
  // plus rho (b2 L_e eps_v')^2 in compression; b1 = b2 = 0: off.
  double bulkLinear = 0.0, bulkQuadratic = 0.0;
  // Mass-proportional damping [1/s] in the pressure phase (default c_s/H) and in the sliding phase.
  double settleDamping = kNotDerived;
  double slideDamping = 0;
  // Stiffness-proportional (Rayleigh beta) damping [s], off by default: it ends the ringing after
  // the first slip (a plateau with constant friction at beta = 0.2 H/(pi c_p), 0.1 of critical in
  // the fundamental thickness mode) but moves mu_s by 4 % there (docs/accuracy_fem.md,
  // "The defaults and why").
  double stiffnessDamping = 0;
  // Damping switched on once the static peak is confirmed (sliding_damping.hpp): mass-proportional
  // towards the slider's velocity [1/s] (default c_s/H, the pressure step's damping: 1/pi of
  // critical in the fundamental thickness-shear mode pi c_s/(2H), and no change of the stable step)
  // and stiffness-proportional [s]. Neither acts before the peak (mu_s is the undamped run's, bit
  // for bit) nor on a plate sliding steadily (docs/accuracy_fem.md, "The defaults and why").
  double peakDamping = kNotDerived;
  double peakStiffnessDamping = 0;
  // When it starts (-fem_peak_damping_start): confirmed (the peak is confirmed), drop (mu fell
  // -friction_peak_drop below its running maximum after the first slip, or confirmed), sliding
  // (the start of step 2: it then acts on the peak too, for the study only).
  enum class DampingStart { Confirmed, Drop, Sliding };
  DampingStart peakDampingStart = DampingStart::Confirmed;
  bool energyAudit = false;  // also integrate the stiffness-proportional dissipation (one more operator pass per step)
};

// Time stepping and the pressure step.
struct FemTimeStep {
  std::optional<double> dt;  // -fem_dt; none: dtSafety x the stable step of the run's grading
  double dtSafety = 0.6;  // docs/accuracy_fem.md: 0.9 gave 1 % mu_s error on the paper mesh and instability with stiffer penalties
  bool dtCheck = true;  // false (testing only): a dt above the stable step is accepted, to test the monitor
  // The integrator the caller chooses (the study's ladders: rk with scheme "4", ssp); the user's
  // -fem_ts_type (the plate's TS has the options prefix fem_) overrides it.
  std::string integrator = "gfverlet";
  std::string rkScheme;  // with integrator "rk": PETSc's TSRKType ("4"); empty: PETSc's default
  // -fem_pressure_step static | dynamic: step 1 as the pressed equilibrium solved directly
  // (pressed_equilibrium.hpp; penalty contact only) or as the ramp and hold in time (the
  // default: CG's sums over ranks make the static state differ between rank counts by ~1e-14,
  // which the post-peak history amplifies past the 1 vs 2 ranks tolerance; docs/accuracy_fem.md, "Cost").
  bool staticPressureStep = false;
  double rampTime = kNotDerived;    // default 20 H/c_s
  double settleTime = kNotDerived;  // default 10 H/c_s
  // Blow-up monitor: non-finite mu(t) or normal force any step; every monitorEvery steps, a
  // non-finite state or kinetic + elastic energy above monitorFactor x (energy put in + reference).
  int monitorEvery = 25;
  double monitorFactor = 10.0;
};

// What a run must determine, as sbm::Request: the shared friction measurement and the run's
// limits; it stops as soon as the observables are known.
struct FemRequest {
  // The shared rule of both models (-friction_ options), its times from the Eq. 2 loading time.
  FrictionMeasurement measurement;
  double slideTime = kNotDerived;  // longest step 2; default 1.5 t_load + the latest mu_k window's end
  bool stopWhenKnown = true;  // false: slide for slideTime whatever the observer knows
  std::vector<double> snapshotTimes;  // field snapshots, times after the start of sliding [s]
};

// Output of a single run.
struct FemOutput {
  std::string output;  // "" = no output file
  bool overwrite = false;
  bool verbose = true;
};

struct FemParameters : FemMesh, FemContact, FemDamping, FemTimeStep, FemRequest, FemOutput {
  // The physical plate (-plate_ options, shared with the spring-block model): size L, thickness
  // H, material, pressure, sliding speed and angle, mean local mu_s and mu_k (graded by -grading_).
  Plate plate;
  // The optional terms' settings (src/fem/terms/: -fem_gravity, ...), each read by its term.
  TermSettings terms;

  FemParameters() : FemParameters(Plate{}) {}
  // Every value at its default for this plate, the derived ones derived from it. A caller that
  // changes the plate afterwards builds its parameters from the changed plate instead.
  explicit FemParameters(const Plate& plate);

  double shearModulus() const { return plate.shearModulus(); }
  double shearWaveSpeed() const;
  // Paper Eq. 2: Delta t_s = mu_s p H / (G v).
  double eq2PeakTime() const { return plate.loadingTime(plate.thickness); }
  // Relative loss of loading slope (dF/dx of the top against G L^2/H) that the penalty springs'
  // compliance causes: tangential G/(H k_t) plus the rocking of the plate on the normal springs
  // under the moment H F, 12 G H/(k_n L^2) (kinematic contact or no contact: 0).
  double penaltySlopeError() const;
};

// The derived defaults, each computed in one place (the constructor and the reader use them).
double defaultPenaltyStiffness(const Plate& plate);  // penaltyFactor G/H
// The measurement's times from the FEM's loading time t_load (Eq. 2 with H) and its steady window.
FrictionMeasurement defaultFemMeasurement(double loadingTime);
// Long enough for the latest window: 1.5 t_load for the peak and its confirmation, then the window.
// The longest sliding step: 1.5 t_load + the latest mu_k window's end; with the normal-stress
// memory at least kMemorySlideLoadingTimes t_load (a leading patch sticks long after the peak).
constexpr double kMemorySlideLoadingTimes = 9.0;
double defaultSlideTime(double loadingTime, const FrictionMeasurement& m, bool withMemory = false);

// One line each for the active effects and the results file: the contact (method, penalties and
// the slope error they carry) and the damping of the sliding step.
std::string describeContact(const FemParameters& q);
std::string describeDamping(const FemParameters& q);
std::string describeFrictionState(const FemParameters& q);  // the law's state (D_c, or -fem_slip_length) in words
// The random surface in one line, l_c also in elements of this size.
std::string describeSurface(const SurfaceSettings& s, double elementSize);

}  // namespace gradfric::fem
