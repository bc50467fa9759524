#pragma once
// One stability layer for both explicit models: the time-step policy (a stable limit, a default
// below it, refusal above it) and the blow-up monitor's checks (finite values, energy bounded by
// the work put in), with one exception that names the quantity, the time and the likely cause.
// PETSc-free.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace gradfric {

// The step a run uses: the user's (refused above the stable limit unless `refuseAbove` is off,
// which only the instability tests do) or the model's default. Throws InputError naming `option`.
struct TimeStepPolicy {
  std::string option;     // "-sbm_dt", "-fem_dt"
  std::string limitText;  // what the limit is, for the message: "the RK4 stability limit of this lattice"
  double stableLimit = 0.0;  // [s]
  bool refuseAbove = true;
  double choose(std::optional<double> requested, double defaultStep) const;
};

// Thrown when a run goes unstable. what(): "<model> run unstable at t = T s (step N): <quantity>.
// Likely cause: <cause>. Run stopped, no results written."
class NumericalInstability : public std::runtime_error {
public:
  NumericalInstability(const std::string& model, const std::string& quantity, double time, std::int64_t step,
                       const std::string& cause);
  const std::string& quantity() const { return quantity_; }
  double time() const { return time_; }
  std::int64_t step() const { return step_; }
  const std::string& cause() const { return cause_; }

private:
  std::string quantity_;
  double time_;
  std::int64_t step_;
  std::string cause_;
};

// The energy balance of a driven, dissipative system: kinetic + elastic energy can never exceed
// the work put in (friction and damping only take energy out). `factor` absorbs the integrator's
// energy error and what the bound does not count; `reference` is an energy scale for the start of
// a run, when the work is still zero [J].
struct EnergyBound {
  double factor = 1.0;
  double reference = 0.0;
  double limit(double workIn) const { return factor * ((workIn > 0 ? workIn : 0.0) + reference); }
  // An empty string if the balance holds, else the violated quantity in words.
  std::string violation(double energy, double workIn, const std::string& workName) const;
};

// The per-step check of mu(t): finite, and below `ceiling` (mu cannot exceed the largest local mu_s
// but by a dynamic overshoot). An empty string if it holds, else the violated quantity in words.
std::string frictionViolation(double mu, double ceiling);

}  // namespace gradfric
