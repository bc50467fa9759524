#include "gradfric/physics/stability.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"

#include <cmath>

namespace gradfric {

double TimeStepPolicy::choose(std::optional<double> requested, double defaultStep) const {
  if (!requested) return defaultStep;
  if (!(*requested > 0) || !std::isfinite(*requested)) throw InputError(option, formatReal(*requested), "> 0 [s]");
  if (refuseAbove && *requested > stableLimit)
    throw InputError(option, formatReal(*requested), "<= " + formatReal(stableLimit) + " s, " + limitText);
  return *requested;
}

NumericalInstability::NumericalInstability(const std::string& model, const std::string& quantity, double time,
                                           std::int64_t step, const std::string& cause)
    : std::runtime_error(model + " run unstable at t = " + formatReal(time) + " s (step " + std::to_string(step) +
                         "): " + quantity + ". Likely cause: " + cause + ". Run stopped, no results written."),
      quantity_(quantity),
      time_(time),
      step_(step),
      cause_(cause) {}

std::string EnergyBound::violation(double energy, double workIn, const std::string& workName) const {
  if (!std::isfinite(energy)) return "the kinetic + elastic energy is not finite";
  if (energy > limit(workIn)) {
    std::string what = "the kinetic + elastic energy " + formatReal(energy) + " J exceeds ";
    if (factor != 1.0) what += formatReal(factor) + " x ";
    what += "(" + workName + " " + formatReal(workIn) + " J";
    if (reference > 0) what += " + " + formatReal(reference) + " J";
    return what + ")";
  }
  return {};
}

std::string frictionViolation(double mu, double ceiling) {
  if (!std::isfinite(mu)) return "mu(t) is not finite";
  if (mu > ceiling) return "mu(t) = " + formatReal(mu) + " exceeds " + formatReal(ceiling);
  return {};
}

}  // namespace gradfric
