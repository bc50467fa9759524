#pragma once
// The per-realisation observables, as data: one row each, taken from the friction summary. The
// results file (/realisations/<name>), the statistics (/statistics/<name>_mean, ...), the printed
// tables and the plot script all loop over this table, so a new observable is its computation
// (FrictionHistory) plus one row in src/physics/observables.cpp. PETSc-free.
#include "gradfric/physics/friction_history.hpp"

#include <string>
#include <vector>

namespace gradfric {

struct Observable {
  std::string name;         // dataset /realisations/<name>; statistics columns <name>_mean, ...
  std::string unit;         // "1" for a pure number
  std::string description;  // one line: the dataset's `description` attribute
  double (*take)(const FrictionSummary&);  // its value for one realisation; NaN: not measured
  bool statistics = false;  // per-point statistics, stored and printed
  std::string title;        // heading of its printed table ("Global static friction")
  bool kinetic = false;     // measured only with the kinetic window (-friction_observables)
};

// Every observable, in the order they are stored and printed.
const std::vector<Observable>& observables();
// The rows with statistics, in the same order: PointStatistics::observables follows it.
std::vector<Observable> statisticsObservables();
// The position of `name` among statisticsObservables(); throws std::out_of_range if it has none.
std::size_t statisticsIndex(const std::string& name);

// A value as the printouts show it: a pure number with 6 decimals (0.911468), anything else with
// 6 significant digits and its unit (0.000123457 s).
std::string formatObservable(const Observable& observable, double value);
// "mu_s = 0.849476, mu_k = 0.624843": a run's observables with statistics, as printed.
std::string observablesText(const FrictionSummary& friction);

}  // namespace gradfric
