// One realisation: build the lattice, integrate, watch the observables, stop once they are known.
#include "gradfric/sbm/model.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/physics/field.hpp"
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/physics/stability.hpp"
#include "gradfric/sbm/integrator.hpp"
#include "gradfric/sbm/reference_lattice.hpp"
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/pressure_coupling.hpp"
#include "gradfric/sbm/quiet_phase.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace gradfric::sbm {

namespace {

PhaseTimer phaseTimer;

// Times one phase with the installed hooks (if any) for the scope's life.
class PhaseScope {
public:
  explicit PhaseScope(Phase phase) : phase_(phase) {
    if (phaseTimer.begin) phaseTimer.begin(phase_);
  }
  ~PhaseScope() noexcept(false) {
    if (phaseTimer.end) phaseTimer.end(phase_);
  }
  PhaseScope(const PhaseScope&) = delete;
  PhaseScope& operator=(const PhaseScope&) = delete;

private:
  Phase phase_;
};

std::vector<double> asVector(const double* data, std::size_t n) { return std::vector<double>(data, data + n); }
std::vector<double> asVector(std::vector<double> data, std::size_t) { return data; }

// What the state law costs on the fast kernel, as measured (bench_sbm_kernel 60, docs/model.md).
const char* const kStateLawCost =
    "per block-step about 1.6x the exponential law (2.2x faster than on the reference kernel); "
    "a 60 x 60 realisation about 1.9x";

std::string likelyCause(const Parameters& p, double stable) {
  std::ostringstream m;
  m << "the time step dt = " << p.timeStep << " s is at or above the stability limit " << stable
    << " s of this lattice (stiffest band";
  if (p.damping > 0) m << ", damping gamma dt = " << p.damping * p.timeStep;
  m << "). Lower -sbm_dt or -sbm_dt_safety";
  return m.str();
}

template <class Lattice>
void integrate(Lattice& lattice, const LatticeStiffness& stiffness, const FrictionField& friction, const Motion& motion,
               const Parameters& p, const Request& q, double stable, PressureCoupling* coupling, Result& result) {
  const int nb = p.blocksPerSide;
  const std::size_t n = std::size_t(nb) * nb;
  const double dt = p.timeStep;
  if (q.measurement.firstSlipMap) {
    result.firstSlipTime.assign(n, std::numeric_limits<double>::quiet_NaN());
    lattice.recordFirstSlips(result.firstSlipTime.data());
  }
  FrictionHistory history(q.measurement, p.plate.normalForce(), dt);
  // The monitor: mu(t) finite and below twice the largest local mu_s at every step; kinetic +
  // elastic energy never above the work done by the slider (trapezoidal rule) every
  // energyCheckInterval steps.
  double work = 0.0, previousFx = 0.0, previousFy = 0.0;
  result.maxLocalStatic = *std::max_element(friction.staticStrength.begin(), friction.staticStrength.end()) /
                          p.normalForcePerBlock();
  const EnergyBound energyBound{1.0 + 1e-3, 0.0};
  auto fail = [&](const std::string& quantity, double t) {
    throw NumericalInstability("the spring-block", quantity, t, lattice.steps(), likelyCause(p, stable));
  };
  std::size_t nextSnapshot = 0;
  double observedMu = 0.0;  // mu(t) the observer holds at the start of the step (the pressure response's load)
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t = lattice.time();
    while (nextSnapshot < q.snapshotTimes.size() && q.snapshotTimes[nextSnapshot] <= t + 0.5 * dt) {
      PhaseScope timed(Phase::Snapshot);
      StressSnapshot snapshot{t, std::vector<double>(n)};
      const auto ux = asVector(lattice.displacementX(), n);
      const auto uy = asVector(lattice.displacementY(), n);
      longitudinalStress(stiffness, p.layerThickness, p.plate.pressure, ux.data(), uy.data(), snapshot.sigmaXOverP.data());
      result.snapshots.push_back(std::move(snapshot));
      ++nextSnapshot;
    }
    const StepObservation o = [&] {
      PhaseScope timed(Phase::Step);
      if (coupling) coupling->apply(observedMu, lattice.law().sites);
      return lattice.step();
    }();
    const double mu = history.observe(t, o.sliderForceX, o.sliderForceY, lattice.slippedBlocks() > 0,
                                      lattice.slippedBlocks() == int(n));
    observedMu = mu;
    // mu(t) cannot exceed the largest local static coefficient but by a dynamic overshoot: twice
    // that is a blow-up, caught at once.
    const std::string muProblem = frictionViolation(mu, 2.0 * result.maxLocalStatic);
    if (!muProblem.empty()) fail(muProblem + " (twice the largest local mu_s)", t);
    if (lattice.steps() > 1)
      work += 0.5 * dt * ((previousFx + o.sliderForceX) * motion.sliderVelocityX +
                          (previousFy + o.sliderForceY) * motion.sliderVelocityY);
    previousFx = o.sliderForceX;
    previousFy = o.sliderForceY;
    bool done = q.endTime > 0 ? t >= q.endTime : history.known() && nextSnapshot == q.snapshotTimes.size();
    done = done || t >= q.maxTime;
    if (done || (q.energyCheckInterval > 0 && lattice.steps() % q.energyCheckInterval == 0)) {
      // State at t + dt against the work up to t plus one more step of the current force.
      const double bound = work + 2.0 * dt * std::fabs(o.sliderForceX * motion.sliderVelocityX +
                                                       o.sliderForceY * motion.sliderVelocityY);
      const auto ux = asVector(lattice.displacementX(), n), uy = asVector(lattice.displacementY(), n);
      const auto vx = asVector(lattice.velocityX(), n), vy = asVector(lattice.velocityY(), n);
      const double tn = lattice.time();
      const LatticeEnergy e = latticeEnergy(stiffness, p.blockMass(), ux.data(), uy.data(), vx.data(), vy.data(),
                                            motion.sliderVelocityX * tn, motion.sliderVelocityY * tn);
      result.energy = e.total();
      result.sliderWork = work;
      const std::string energyProblem = energyBound.violation(e.total(), bound, "the work done by the slider");
      if (!energyProblem.empty()) fail(energyProblem, t);
    }
    if (done) break;
  }
  result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.steps = lattice.steps();
  result.endTime = lattice.time();
  result.friction = history.summary();
  if (coupling) result.pressureCoupling = coupling->record();
}

// The load-dependent pressure of a run, if the scene asks for one: the shape g on this lattice
// (zero mean under the static pressure's weights) and the law's base strengths per block.
std::optional<PressureCoupling> pressureCouplingFor(const Parameters& p, const Grading& grading,
                                                    const FrictionField& friction) {
  if (!p.pressureResponse.active()) return std::nullopt;
  const int nb = p.blocksPerSide;
  std::vector<double> weights;  // p_i^0 / p, empty when the static pressure is uniform
  if (grading.fields && grading.fields->pressure) {
    weights = blockProperties(p, grading).pressure;
    for (double& w : weights) w /= p.plate.pressure;
  }
  const double angle = p.plate.slidingAngle;
  // Under -pressure_response_select grading: the g measured under this run's grading.
  std::vector<double> shape = pressureResponseShape(selectedFor(p.pressureResponse, grading, angle), nb,
                                                    p.plate.length, p.plate.thickness, angle, weights);
  return PressureCoupling(friction, nb, std::move(shape), slidingCoordinates(nb, p.plate.length, angle),
                          std::move(weights), p.plate.thickness);
}

}  // namespace

void setPhaseTimer(PhaseTimer timer) { phaseTimer = timer; }

// The law a FastLattice is built on under a load-dependent pressure with the quiet-phase jump:
// strengths that hold no longer than the real ones during the quiet phase, so that the jump ends
// at or before the first slip (the real strengths are set before the first integrated step).
// While every block rests, mu(t_n) = sum_i K_s,i v t_n / (p L^2) rises linearly; the first slip
// comes no later than the first block with g_i <= 0 (its threshold never rises) would slip at its
// static strength: mu up to that step bounds every mu the quiet phase sees.
template <class Law>
Law quietPhaseLaw(const Law& law, const PressureCoupling& coupling, const LatticeStiffness& stiffness,
                  const Motion& motion, double normalForce) {
  const int nb = stiffness.blocksPerSide;
  const FrictionSites& base = coupling.perSite();
  std::int64_t latest = std::int64_t(1) << 52;
  double sliderSum = 0.0;
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) {
      sliderSum += stiffness.sliderAt(r, c);
      const std::size_t i = std::size_t(r) * nb + c;
      if (coupling.shape()[i] <= 0.0)
        latest = std::min(latest, firstSlipStepAtRest<Law>(stiffness.sliderAt(r, c), base.staticStrength[i], motion, latest));
    }
  const double speed = std::hypot(motion.sliderVelocityX, motion.sliderVelocityY);
  const double muBound = sliderSum * speed * double(latest + 1) * motion.timeStep / normalForce * (1.0 + 1e-9);
  Law bounded = law;
  bounded.sites = coupling.quietPhaseSites(muBound);
  return bounded;
}

Result simulate(const Parameters& parameters, const Grading& grading, const Request& q, StreamKey key, Kernel kernel) {
  std::optional<PhaseScope> setup(std::in_place, Phase::Setup);
  const Parameters& p = parameters;
  const LatticeStiffness stiffness = buildStiffness(p, grading);
  const FrictionField friction = buildFriction(p, grading, key);
  std::optional<PressureCoupling> coupling = pressureCouplingFor(p, grading, friction);
  Motion motion = motionOf(p, p.timeStep, p.damping);
  motion.fixedStrengths = !coupling;  // the pressure rescales the strengths every step
  setup.reset();
  Result result;
  result.redrawnBlocks = friction.redrawnBlocks;
  const double stable = stableTimeStep(p, grading);
  // The law's template parameter selects the compiled kernels (friction_laws.hpp).
  PressureCoupling* couple = coupling ? &*coupling : nullptr;
  const FrictionSites sites = coupling ? coupling->perSite() : FrictionSites(friction);
  // A law with a per-block state: on either kernel. Under a load-dependent pressure neither jumps
  // its quiet phase (their constructors see Motion::fixedStrengths), so no bounded law is needed.
  const std::size_t blocks = std::size_t(p.blocksPerSide) * p.blocksPerSide;
  if (withStateFrictionLaw(p.frictionLaw, sites, blocks, [&](auto law) {
        using Law = decltype(law);
        if (kernel == Kernel::Fast) {
          FastLattice<Law> lattice(stiffness, std::move(law), motion);
          integrate(lattice, stiffness, friction, motion, p, q, stable, couple, result);
        } else {
          ReferenceLattice<Law> lattice(stiffness, std::move(law), motion);
          integrate(lattice, stiffness, friction, motion, p, q, stable, couple, result);
        }
      }))
    return result;
  withFrictionLaw(p.frictionLaw, sites, [&](auto law) {
    using Law = decltype(law);
    if (kernel == Kernel::Fast && couple && motion.skipIdle) {
      // Built on bounded strengths (an exact quiet-phase jump), then given the real ones: the
      // first apply() in integrate() sets them before the first integrated step.
      FastLattice<Law> lattice(stiffness, quietPhaseLaw(law, *couple, stiffness, motion, p.plate.normalForce()), motion);
      integrate(lattice, stiffness, friction, motion, p, q, stable, couple, result);
    } else if (kernel == Kernel::Fast) {
      FastLattice<Law> lattice(stiffness, std::move(law), motion);
      integrate(lattice, stiffness, friction, motion, p, q, stable, couple, result);
    } else {
      ReferenceLattice<Law> lattice(stiffness, std::move(law), motion);
      integrate(lattice, stiffness, friction, motion, p, q, stable, couple, result);
    }
  });
  return result;
}

double regimeNumber(const Parameters& p) {
  const Plate& plate = p.plate;
  return plate.shearModulus() * p.frictionLaw.slipLength /
         (p.layerThickness * plate.pressure * (plate.muStatic - plate.muKinetic));
}

std::vector<std::string> activeEffects(const Parameters& p, const Grading& g, const Request& q) {
  std::vector<std::string> effects;
  std::ostringstream s;
  s << p.blocksPerSide << " x " << p.blocksPerSide << " blocks, axial + diagonal springs (nonlinear geometry)";
  effects.push_back(s.str());
  const bool fieldE = g.fields && g.fields->modulus;
  const bool fieldMu = g.fields && (g.fields->muStatic || g.fields->muKinetic || g.fields->pressure);
  effects.push_back(g.gradesModulus() ? "graded Young's modulus (" + describe(g) + "), series spring stiffness"
                    : fieldE          ? std::string("Young's modulus from a property field, series spring stiffness ") +
                                   (g.fields->modulus->variesAlongY() ? "per block (E varies along y)" : "per block column")
                                      : "uniform Young's modulus: uniform-stiffness kernel");
  effects.push_back(g.gradesFriction() ? "graded friction coefficients (" + describe(g) + ")"
                    : fieldMu          ? "friction strengths mu p l^2 from property fields"
                                       : "uniform mean friction coefficients");
  if (g.fields)
    for (const auto& line : describeFields(*g.fields)) effects.push_back(line);
  const SurfaceSettings surface = p.surfaceOf();
  if (surface.dispersed()) {
    if (surface.kind == SurfaceKind::Blocks) {
      std::ostringstream d;
      d << "random surface: sigma_s = " << surface.sigmaStatic << ", sigma_k = " << surface.sigmaKinetic
        << ", one draw per block (l_c = the block, redrawn until 0 < mu_k,i <= mu_s,i)";
      effects.push_back(d.str());
    } else {
      effects.push_back(describeSurfaceField(surface, p.spacing(), "blocks") + ", each block its area's average");
    }
  } else {
    effects.push_back("no dispersion: no random surface, no per-block coefficients");
  }
  effects.push_back("friction law: " + describeFrictionLaw(p.frictionLaw));
  const bool stateLaw = isStateLaw(p.frictionLaw);
  if (stateLaw) {
    effects.push_back(std::string("per-block state theta, advanced once per step from the block's slip; its strength is "
                                  "the static threshold and the sliding force. Fast kernel, per-block state: ") +
                      kStateLawCost);
    std::ostringstream k;
    k.precision(3);
    k << "regime number kappa = K_s D_c / (F_n (mu_s - mu_k)) = G D_c / (l_z p (mu_s - mu_k)) = " << regimeNumber(p)
      << (regimeNumber(p) < 1 ? " < 1: dynamic onset (a block weakens faster than its slider reloads)"
                              : " >= 1: smooth onset (every block's slider outweighs its weakening)");
    effects.push_back(k.str());
  }
  effects.push_back(p.damping > 0 ? "viscous damping gamma = " + formatReal(p.damping) + " 1/s" : "no damping");
  if (p.pressureResponse.active()) {
    effects.push_back(p.pressureResponse.describe() +
                      "; mu(t) of the previous step (explicit), strengths mu_s,i F_n,i and mu_k,i F_n,i rescaled every step");
    const int nb = p.blocksPerSide;
    const double angle = p.plate.slidingAngle;
    // Under -pressure_response_select grading the shape of this grading, if a file holds one.
    const ResponseGrading key = responseGradingOf(g, angle);
    const auto& measured = p.pressureResponse.measured;
    const bool shown = !p.pressureResponse.perGrading ||
                       std::any_of(measured.begin(), measured.end(),
                                   [&](const MeasuredResponse& m) { return sameGrading(m.grading, key); });
    if (shown) {
      const std::vector<double> shape = pressureResponseShape(selectedFor(p.pressureResponse, g, angle), nb,
                                                              p.plate.length, p.plate.thickness, angle);
      const ShapeMoments m = shapeMoments(shape, slidingCoordinates(nb, p.plate.length, angle));
      const auto [lo, hi] = std::minmax_element(shape.begin(), shape.end());
      std::ostringstream text;
      text.precision(4);
      text << "pressure response g on the blocks" << (p.pressureResponse.perGrading ? " (" + key.describe() + ")" : "")
           << ": " << *lo << " (most unloaded) to " << *hi << " (most loaded), first moment "
           << m.moment / p.plate.thickness << " H along the sliding direction, mean " << m.mean;
      effects.push_back(text.str());
    }
    effects.push_back(!p.skipIdle ? "every block stepped from t = 0 (-sbm_skip_idle false)"
                      : stateLaw  ? "every block stepped from t = 0 (with the state law the quiet phase is jumped "
                                    "only under a constant pressure)"
                                  : "idle work skipped: the quiet phase before the first slip in closed form, ended at "
                                    "or before the first slip under the rising load (bit for bit)");
  } else {
    const bool verlet = p.integrator == Integrator::VelocityVerlet;
    effects.push_back(p.skipIdle ? std::string("idle work skipped: the phase before the first slip in closed form") +
                                       (stateLaw ? " (theta stays 0)" : "") +
                                       (verlet ? (stateLaw ? ", then the active set with held tiles, which heal (bit for bit)"
                                                           : ", then the active set with held tiles (bit for bit)")
                                               : " (bit for bit)")
                                 : "every block stepped from t = 0 (-sbm_skip_idle false)");
  }
  effects.push_back(p.smallStrain ? "small-strain springs: forces linearised about the rest directions (-sbm_spring)"
                                  : "exact springs: force along the current direction of each spring");
  effects.push_back("sliding angle theta = " + formatReal(p.plate.slidingAngle) + " degree");
  std::string observed = "observables: mu_s";
  if (q.measurement.kinetic) observed += ", mu_k";
  if (q.measurement.firstSlipMap) observed += ", first-slip map";
  if (!q.snapshotTimes.empty()) observed += ", " + std::to_string(q.snapshotTimes.size()) + " sigma_x/p snapshots";
  else observed += " (no stress field computed)";
  effects.push_back(observed);
  effects.push_back(q.endTime > 0 ? "fixed duration " + formatReal(q.endTime) + " s"
                                  : "stops once the observables are determined");
  return effects;
}

}  // namespace gradfric::sbm
