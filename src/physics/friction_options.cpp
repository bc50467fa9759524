#include "gradfric/physics/friction_options.hpp"

#include "gradfric/core/format.hpp"
#include "gradfric/core/input_error.hpp"
#include "gradfric/physics/observables.hpp"

#include <petscsys.h>

#include <algorithm>
#include <string>
#include <utility>

namespace gradfric {

namespace {

void refuseOldNames() {
  const std::pair<const char*, const char*> renamed[] = {
      {"-sbm_observables", "-friction_observables"},   {"-sbm_peak_drop", "-friction_peak_drop"},
      {"-sbm_peak_hold", "-friction_peak_hold"},       {"-sbm_muk_delay", "-friction_muk_delay"},
      {"-sbm_muk_width", "-friction_muk_width"},       {"-sbm_history_interval", "-friction_history_interval"},
      {"-fem_kinetic_window_start", "-friction_muk_delay"}, {"-fem_kinetic_window_length", "-friction_muk_width"}};
  for (const auto& [old, now] : renamed) refuseRenamedOption(old, now, "both models measure friction by one rule");
}

}  // namespace

FrictionMeasurement readFrictionMeasurement(MPI_Comm comm, RunParameters* record, double load,
                                            const MeasurementDefaults& window) {
  refuseOldNames();
  OptionReader o(comm, "friction_", "Friction measurement (both models): mu(t) = |F|/(p L^2), mu_s, mu_k", record);
  FrictionMeasurement m;
  const std::vector<std::string> choices = {"mu_s", "mu_k", "first_slip"};
  // The table's other rows come with mu_s (physics/observables.hpp): -help names them from it.
  std::string alongside;
  for (const Observable& row : gradfric::observables())
    if (std::find(choices.begin(), choices.end(), row.name) == choices.end())
      alongside += (alongside.empty() ? "" : ", ") + row.name;
  const auto observables = o.choiceList("observables", window.observables, choices,
                                        "what the run must determine; it stops once these are known (" + alongside +
                                            " come with mu_s)");
  auto wants = [&](const char* name) { return std::find(observables.begin(), observables.end(), name) != observables.end(); };
  m.kinetic = wants("mu_k");
  m.firstSlipMap = wants("first_slip");
  auto derived = [&](const char* name, double factor, const char* help, const char* text) {
    if (auto v = o.realIfSet(name, "s", help, text)) {
      o.requireNonNegative(name, *v, "s");
      return *v;
    }
    o.recordDerived(name, factor * load, "s", std::string(help) + " = " + text);
    return factor * load;
  };
  m.historyInterval = derived("history_interval", 1e-3, "sampling interval of the stored mu(t) history", "t_load / 1000");
  m.kineticDelay = derived("muk_delay", 0.5, "start of the mu_k window after the peak", "0.5 t_load");
  m.kineticWidth = derived("muk_width", 1.0, "width of the mu_k window", "t_load");
  m.kineticSteadyTolerance =
      o.real("muk_steady_tol", window.steadyTolerance, "1",
             "steady mu_k window: the means of its 4 quarters spread by at most this fraction of its mean, else "
             "it slides later (the run goes on); 0: the fixed window");
  o.requireRange("muk_steady_tol", m.kineticSteadyTolerance, 0.0, 1.0, "0 <= muk_steady_tol <= 1");
  {  // derived: the model's factor of t_load, never before the window's first start
    const char* help = "latest start of a sliding mu_k window after the peak (then: not steady)";
    if (auto v = o.realIfSet("muk_latest_delay", "s", help, formatReal(window.latestDelayFactor) + " t_load")) {
      o.requireNonNegative("muk_latest_delay", *v, "s");
      m.kineticLatestDelay = *v;
      if (m.kineticSteadyTolerance > 0 && m.kineticLatestDelay < m.kineticDelay)
        throw InputError(o.fullName("muk_latest_delay"), formatReal(m.kineticLatestDelay),
                         ">= -friction_muk_delay = " + formatReal(m.kineticDelay) + " [s]");
    } else {
      m.kineticLatestDelay = std::max(window.latestDelayFactor * load, m.kineticDelay);
      o.recordDerived("muk_latest_delay", m.kineticLatestDelay, "s",
                      std::string(help) + " = max(" + formatReal(window.latestDelayFactor) + " t_load, muk_delay)");
    }
  }
  m.peakHold = derived("peak_hold", 0.25, "peak confirmed once every site slid and no new maximum for this long",
                       "0.25 t_load");
  m.peakDrop = o.real("peak_drop", m.peakDrop, "1", "peak confirmed once every site slid and mu(t) fell this fraction below it");
  o.requireRange("peak_drop", m.peakDrop, 0.0, 1.0, "0 <= peak_drop <= 1");
  if (m.kinetic && !(m.kineticWidth > 0))
    throw InputError(o.fullName("muk_width"), formatReal(m.kineticWidth), "> 0 [s] when mu_k is requested");
  return m;
}

}  // namespace gradfric
