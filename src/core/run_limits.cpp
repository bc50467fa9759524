#include "gradfric/core/run_limits.hpp"

#include "gradfric/core/input_error.hpp"

#include <cmath>
#include <cstdlib>

namespace gradfric {

namespace {

bool startsWithAny(const std::string& name, const std::vector<std::string>& prefixes) {
  for (const auto& prefix : prefixes)
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

// Decades between a value and its default; 0 when either is zero or not a number.
double decadesFromDefault(const ResolvedOption& option) {
  const double value = std::strtod(option.value.c_str(), nullptr);
  const double fallback = std::strtod(option.fallback.c_str(), nullptr);
  if (value == 0 || fallback == 0 || !std::isfinite(value) || !std::isfinite(fallback)) return 0;
  return std::fabs(std::log10(std::fabs(value) / std::fabs(fallback)));
}

}  // namespace

const ResolvedOption* firstUserSet(const RunParameters* record, const std::vector<std::string>& names) {
  if (!record) return nullptr;
  for (const auto& name : names) {
    const ResolvedOption* option = record->find(name);
    if (option && option->origin == OptionOrigin::User) return option;
  }
  return nullptr;
}

const ResolvedOption* furthestFromDefault(const RunParameters* record, const std::vector<std::string>& prefixes) {
  if (!record) return nullptr;
  const ResolvedOption* furthest = nullptr;
  double largest = -1;
  for (const auto& option : record->all()) {
    if (option.origin != OptionOrigin::User || option.fallback.empty() || !startsWithAny(option.name, prefixes))
      continue;
    const double decades = decadesFromDefault(option);
    if (decades > largest) {
      largest = decades;
      furthest = &option;
    }
  }
  return furthest;
}

void requireRunLength(const RunParameters* record, double duration, double dt, double automaticDt,
                      const std::string& dtName, const std::vector<std::string>& durationNames,
                      const std::vector<std::string>& physicalPrefixes, const std::string& context) {
  const double steps = duration / dt;
  if (steps <= kMaxTimeSteps) return;  // also refuses NaN
  const std::string cap = "at most 1e9 time steps";
  const std::string detail = " (" + context + ": " + formatReal(duration) + " s at dt = " + formatReal(dt) +
                             " s is " + formatReal(steps) + " steps)";
  if (const ResolvedOption* step = firstUserSet(record, {dtName}))
    if (duration / automaticDt <= kMaxTimeSteps) throw InputError(dtName, step->value, "a step that needs " + cap + detail);
  // A physical value thousands of times its default (-sbm_E 1e300) is the likelier culprit than
  // a duration the user set.
  const ResolvedOption* physical = furthestFromDefault(record, physicalPrefixes);
  const std::string physicalText = "a value for which the run needs " + cap + detail;
  if (physical && decadesFromDefault(*physical) >= 3) throw InputError(physical->name, physical->value, physicalText);
  if (const ResolvedOption* length = firstUserSet(record, durationNames))
    throw InputError(length->name, length->value, "a duration of " + cap + detail);
  if (physical) throw InputError(physical->name, physical->value, physicalText);
  throw InputError("this run would need more than 1e9 time steps" + detail);
}

void requireResolvedTimescale(const RunParameters* record, double timescale, double dt, const std::string& dtName,
                              const std::vector<std::string>& physicalPrefixes, const std::string& timescaleName) {
  if (timescale / dt >= kMinStepsPerTimescale) return;  // also refuses NaN
  const std::string allowed = "a value for which the " + timescaleName + " spans at least 10 time steps (" +
                              timescaleName + " " + formatReal(timescale) + " s, dt = " + formatReal(dt) + " s)";
  if (const ResolvedOption* physical = furthestFromDefault(record, physicalPrefixes))
    if (decadesFromDefault(*physical) > 0) throw InputError(physical->name, physical->value, allowed);
  if (const ResolvedOption* step = firstUserSet(record, {dtName})) throw InputError(dtName, step->value, allowed);
  throw InputError("this run resolves nothing: " + allowed.substr(allowed.find("the ")));
}

}  // namespace gradfric
