// The /statistics columns (include/gradfric/campaign/statistics_columns.hpp).
#include "gradfric/campaign/statistics_columns.hpp"

#include <cmath>
#include <limits>

#include "gradfric/physics/observables.hpp"

namespace gradfric::campaign {

namespace {

const char* kMeanInterval = "95 % Student t, n - 1 degrees of freedom";
const char* kRelativeInterval =
    "95 % Student t half-width: the propagated standard error x t(0.975, min(n, n_0) - 1), or with common random "
    "numbers the paired differences' x t(0.975, pairs - 1)";

// One real column of an observable's statistics (docs/ensemble.md has the formulas).
struct Column {
  const char* suffix;
  bool inObservableUnit;  // else a pure number (relative variations)
  std::string (*describe)(const std::string& of);
  const char* interval;  // "" if the column is not an interval
  double (*value)(const ObservableStatistics&);
  bool againstReference = false;  // a relative variation: none in a file without a reference point
};

const Column kColumns[] = {
    {"mean", true, [](const std::string& of) { return "mean of " + of + " over the finished realisations"; }, "",
     [](const ObservableStatistics& s) { return s.summary.mean; }},
    {"std", true, [](const std::string& of) { return "sample standard deviation (n - 1) of " + of; }, "",
     [](const ObservableStatistics& s) { return s.summary.stdDev; }},
    {"stderr", true, [](const std::string& of) { return "standard error of the mean of " + of; }, "",
     [](const ObservableStatistics& s) { return s.summary.stdError; }},
    {"ci95_low", true,
     [](const std::string& of) { return "lower end of the 95 % confidence interval of the mean of " + of; },
     kMeanInterval, [](const ObservableStatistics& s) { return s.summary.ciLow; }},
    {"ci95_high", true,
     [](const std::string& of) { return "upper end of the 95 % confidence interval of the mean of " + of; },
     kMeanInterval, [](const ObservableStatistics& s) { return s.summary.ciHigh; }},
    {"relative", false,
     [](const std::string& of) { return "(" + of + " - " + of + "_0) / " + of + "_0 against /sweep/reference_point"; },
     "", [](const ObservableStatistics& s) { return s.relative.value; }, true},
    {"relative_ci95", false, [](const std::string& of) { return "95 % confidence half-width of " + of + "_relative"; },
     kRelativeInterval, [](const ObservableStatistics& s) { return s.relative.halfWidth; }, true},
};

io::StatisticColumn column(std::string name, std::string units, std::string description, bool integer = false,
                           const std::string& interval = "") {
  io::StatisticColumn c{std::move(name), std::move(units), std::move(description), integer, {}};
  if (!interval.empty()) c.attributes.emplace_back("interval", interval);
  return c;
}

}  // namespace

std::vector<io::StatisticColumn> statisticsColumns(StatisticsFile file) {
  const bool relative = file != StatisticsFile::FemRun;
  std::vector<io::StatisticColumn> out{column("finished", "1", "realisations finished", true)};
  for (const Observable& o : statisticsObservables()) {
    for (const Column& c : kColumns)
      if (relative || !c.againstReference)
        out.push_back(column(o.name + "_" + c.suffix, c.inObservableUnit ? o.unit : "1", c.describe(o.name), false,
                             c.interval));
    out.push_back(column(o.name + "_count", "1", "finite values of " + o.name + " used for the statistics", true));
  }
  out.push_back(column("peaks_unconfirmed", "1",
                       file == StatisticsFile::SpringBlock
                           ? "realisations whose peak was not confirmed before the run ended (-sbm_t_max, -fem_slide_time)"
                           : "realisations whose peak was not confirmed before the run ended (-fem_slide_time)",
                       true));
  return out;
}

namespace {

const char* const kBarFields[][2] = {
    {"error", "U / |value|: the relative discretisation uncertainty of the point's mean (NaN: not measured)"},
    {"order", "observed order p of the ladder's fit phi_0 + alpha h^p (NaN: not measured)"},
    {"safety_factor", "safety factor Fs of the procedure: 1.25 in the asymptotic range, 3 otherwise (NaN: not measured)"},
    {"extrapolated", "phi_0, the value the error fit extrapolates to (NaN: not measured)"},
    {"half_width", "the 95 % statistical half-width included in U, relative (NaN: not measured)"}};

// The per-point text of a field, one line per point.
std::string perPoint(const std::vector<study::StudyBar>& bars, std::string (*field)(const study::StudyBar&)) {
  std::string text;
  for (std::size_t p = 0; p < bars.size(); ++p) text += (p ? "\n" : "") + field(bars[p]);
  return text;
}

}  // namespace

std::vector<io::StatisticColumn> discretisationColumns(const std::string& observable,
                                                       const std::vector<study::StudyBar>& bars) {
  std::vector<io::StatisticColumn> columns;
  for (const auto& [field, description] : kBarFields)
    columns.push_back(column(observable + "_discretisation_" + field, "1", description, false,
                             "Eca and Hoekstra (2014) least-squares procedure on the study's ladder "
                             "(docs/verification.md), not a statistical interval"));
  auto& attributes = columns.front().attributes;  // one line per point
  attributes.emplace_back("convergence", perPoint(bars, [](const study::StudyBar& b) {
                            return b.judged ? verification::toString(b.verdict.convergence) : std::string("not in the study");
                          }));
  attributes.emplace_back("fit", perPoint(bars, [](const study::StudyBar& b) {
                            return b.measured ? std::string(verification::toString(b.verdict.fit)) : std::string("none");
                          }));
  attributes.emplace_back("ladder", perPoint(bars, study::ladderText));
  attributes.emplace_back("basis", perPoint(bars, study::describeBar));
  return columns;
}

std::vector<std::pair<std::string, std::vector<double>>> discretisationValues(const std::string& observable,
                                                                              const std::vector<study::StudyBar>& bars) {
  std::vector<std::pair<std::string, std::vector<double>>> values;
  for (const auto& field : kBarFields) values.emplace_back(observable + "_discretisation_" + field[0], std::vector<double>{});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const study::StudyBar& b : bars) {
    const verification::Verdict& v = b.verdict;
    const double fields[] = {v.relative(), v.order, v.safetyFactor, v.extrapolated, v.halfWidth / std::fabs(v.value)};
    for (std::size_t k = 0; k < values.size(); ++k) values[k].second.push_back(b.measured ? fields[k] : nan);
  }
  return values;
}

std::vector<io::StatisticColumn> targetColumns() {
  return {column("target_half_width", "1",
                 "95 % CI half-width reached of the quantity -ensemble_target bounds (-ensemble_target_type)", false,
                 "95 % Student t half-width (as mu_s_ci95_* and mu_s_relative_ci95)"),
          column("target_met", "1", "1 if the point met -ensemble_target, 0 if it stopped at -ensemble_target_max",
                 true)};
}

StatisticsValues statisticsValues(const std::vector<PointStatistics>& statistics, bool relative) {
  StatisticsValues out;
  auto integer = [&](const std::string& name, auto get) {
    std::vector<int> v;
    for (const auto& s : statistics) v.push_back(get(s));
    out.integer.emplace_back(name, v);
  };
  integer("finished", [](const PointStatistics& s) { return s.finished; });
  const std::vector<Observable> rows = statisticsObservables();
  for (std::size_t o = 0; o < rows.size(); ++o) {
    for (const Column& c : kColumns) {
      if (!relative && c.againstReference) continue;
      std::vector<double> v;
      for (const auto& s : statistics) v.push_back(c.value(s.observables.at(o)));
      out.real.emplace_back(rows[o].name + "_" + c.suffix, v);
    }
    integer(rows[o].name + "_count", [o](const PointStatistics& s) { return s.observables.at(o).summary.count; });
  }
  integer("peaks_unconfirmed", [](const PointStatistics& s) { return s.peaksUnconfirmed; });
  return out;
}

}  // namespace gradfric::campaign
