// The observable table (include/gradfric/physics/observables.hpp).
#include "gradfric/physics/observables.hpp"

#include <cstdio>
#include <stdexcept>

namespace gradfric {

const std::vector<Observable>& observables() {
  static const std::vector<Observable> table = {
      {"mu_s", "1", "global static friction coefficient: the maximum of mu(t) at the transition",
       [](const FrictionSummary& f) { return f.muStatic; }, true, "Global static friction", false},
      {"mu_k", "1", "global kinetic coefficient: mean of mu(t) over the window after the peak; NaN: none",
       [](const FrictionSummary& f) { return f.muKinetic; }, true, "Global kinetic friction", true},
      {"peak_time", "s", "time of the peak of mu(t)", [](const FrictionSummary& f) { return f.peakTime; }, false,
       "Time of the static peak", false},
      {"detachment_time", "s",
       "time at which every site (SBM block; FEM bottom node: slipped or lost contact) had slipped at least once: "
       "the detachment front crossed the plate; NaN: never",
       [](const FrictionSummary& f) { return f.detachmentTime; }, true, "Detachment time", false},
  };
  return table;
}

std::vector<Observable> statisticsObservables() {
  std::vector<Observable> out;
  for (const Observable& o : observables())
    if (o.statistics) out.push_back(o);
  return out;
}

std::size_t statisticsIndex(const std::string& name) {
  const std::vector<Observable> rows = statisticsObservables();
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].name == name) return i;
  throw std::out_of_range("no statistics of the observable " + name);
}

std::string formatObservable(const Observable& observable, double value) {
  char text[64];
  if (observable.unit == "1")
    std::snprintf(text, sizeof text, "%.6f", value);
  else
    std::snprintf(text, sizeof text, "%.6g %s", value, observable.unit.c_str());
  return text;
}

std::string observablesText(const FrictionSummary& friction) {
  std::string out;
  for (const Observable& o : statisticsObservables())
    out += (out.empty() ? "" : ", ") + o.name + " = " + formatObservable(o, o.take(friction));
  return out;
}

}  // namespace gradfric
