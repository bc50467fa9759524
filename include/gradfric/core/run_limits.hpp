#pragma once
// Caps on what a run may cost, checked before any work, and the option to blame when a
// combination of finite values would make a run endless (-sbm_dt 1e-300, -sbm_mu_s 1e300).
#include "gradfric/core/options.hpp"

#include <string>
#include <vector>

namespace gradfric {

// Time steps of one run (one SBM realisation, one FEM run): 1e9 is ~10^4 times the default
// scenes and days of wall time even for the smallest lattice.
constexpr double kMaxTimeSteps = 1e9;

// The option the user set, among `names` (in this order of preference), or nullptr.
const ResolvedOption* firstUserSet(const RunParameters* record, const std::vector<std::string>& names);

// The real option the user set furthest from its built-in default (in decades), among those whose
// name starts with one of `prefixes` ("-sbm_", "-plate_", ...), or nullptr.
const ResolvedOption* furthestFromDefault(const RunParameters* record, const std::vector<std::string>& prefixes);

// Refuses a run of steps = duration / dt above kMaxTimeSteps. Blames, in this order: the step
// if the user set it and the automatic step would have been fine; the duration options the user
// set (durationNames); else the physical option furthest from its default (the loading time or
// the stable step it changed); else the run as a whole. `context` describes the run in the message.
void requireRunLength(const RunParameters* record, double duration, double dt, double automaticDt,
                      const std::string& dtName, const std::vector<std::string>& durationNames,
                      const std::vector<std::string>& physicalPrefixes, const std::string& context);

// Refuses a run whose characteristic time (the SBM's loading time, the FEM's Eq. 2 peak time)
// spans fewer than kMinStepsPerTimescale steps: nothing would be resolved (-sbm_E 1e300 makes the
// loading time 1e-296 s). Blames the physical option furthest from its default, else the step.
constexpr double kMinStepsPerTimescale = 10;
void requireResolvedTimescale(const RunParameters* record, double timescale, double dt, const std::string& dtName,
                              const std::vector<std::string>& physicalPrefixes, const std::string& timescaleName);

}  // namespace gradfric
