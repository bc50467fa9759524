#pragma once
// One realisation of the spring-block model: build the lattice for a grading and a random
// stream, integrate, and return the observables asked for. No MPI, no PETSc inside (the core
// library): the ensemble layer spreads realisations over ranks.
#include "gradfric/core/random_stream.hpp"
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/grading.hpp"
#include "gradfric/sbm/parameters.hpp"
#include "gradfric/sbm/pressure_coupling.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gradfric::sbm {

struct StressSnapshot {
  double time;
  std::vector<double> sigmaXOverP;  // N_b x N_b, row-major: index = row * N_b + column (column along x)
};

struct Result {
  FrictionSummary friction;  // mu(t) history (with F_x, F_y), mu_s, peak time, mu_k, first slip: the shared observer's
  std::vector<double> firstSlipTime;  // N_b x N_b as above; NaN where a block never slipped; empty if not asked
  std::vector<StressSnapshot> snapshots;
  std::int64_t steps = 0;
  double endTime = 0.0;      // simulated time reached [s]
  double wallSeconds = 0.0;  // elapsed wall time of the integration
  int redrawnBlocks = 0;     // local coefficients redrawn to keep 0 < mu_k,i <= mu_s,i
  // Energy balance at the end [J]: kinetic + elastic never exceeds the slider's work (checked).
  double energy = 0.0;
  double sliderWork = 0.0;
  double maxLocalStatic = 0.0;  // the largest local mu_s,i: mu(t) stays below it (checked)
  PressureCouplingRecord pressureCoupling;  // the load-dependent pressure's totals (inactive: none)
};

// simulate() throws gradfric::NumericalInstability (physics/stability.hpp) when the run blows up:
// a non-finite mu(t) or one above twice the largest local mu_s (checked every step), or kinetic plus
// elastic energy above the work the slider has done (every Request::energyCheckInterval steps).

// Fast: the production kernel. Reference: the plain kernel the tests compare against.
enum class Kernel { Fast, Reference };

// Timing hooks around simulate()'s phases; none by default (the core has no PETSc). The PETSc
// library installs its log events (log_events.hpp) so that -log_view shows them.
enum class Phase { Setup = 0, Step = 1, Snapshot = 2 };
struct PhaseTimer {
  void (*begin)(Phase) = nullptr;
  void (*end)(Phase) = nullptr;
};
void setPhaseTimer(PhaseTimer timer);

Result simulate(const Parameters& parameters, const Grading& grading, const Request& request, StreamKey key,
                Kernel kernel = Kernel::Fast);

// The spring-block regime number of a state law (docs/model.md): the slider stiffness per area
// G / l_z against the law's weakening rate at onset p (mu_s - mu_k) / D_c, with the plate's mean
// coefficients; the FEM's kappa with H -> l_z. Below 1 a block's onset is dynamic.
double regimeNumber(const Parameters& parameters);

// The effects a scene switches on, in words (printed at the start of a run).
std::vector<std::string> activeEffects(const Parameters& parameters, const Grading& grading, const Request& request);

}  // namespace gradfric::sbm
