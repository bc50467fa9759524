#pragma once
// The /statistics columns of every ensemble and FEM sweep file, generated from the observable
// table (physics/observables.hpp): their names, units, descriptions and interval attributes, and
// their values from the statistics of each point. One list for the writers (gradfric, the FEM
// sweep) and the layout; nothing parses a column's name back.
#include "gradfric/campaign/statistics.hpp"
#include "gradfric/core/study_table.hpp"
#include "gradfric/io/results_file.hpp"

#include <string>
#include <utility>
#include <vector>

namespace gradfric::campaign {

// The file the columns are for: a spring-block ensemble's, a FEM sweep's, or a single FEM run's,
// which has no reference point and so no relative variation (and whose descriptions name the
// FEM's options alone).
enum class StatisticsFile { SpringBlock, FemSweep, FemRun };
// finished, then per observable with statistics <name>_mean, _std, _stderr, _ci95_low, _ci95_high,
// _relative, _relative_ci95 (real; not in a single FEM run's file) and <name>_count (integer),
// then peaks_unconfirmed.
std::vector<io::StatisticColumn> statisticsColumns(StatisticsFile file = StatisticsFile::SpringBlock);
// Each point's discretisation bar of an observable (core/study_table.hpp), both models alike, as
// fields: <observable>_discretisation_error (U relative to the value), _order, _safety_factor,
// _extrapolated, _half_width (NaN: not measured); the error column carries one line per point of
// each text field: convergence, fit, ladder ("mesh:value ...") and basis (for people).
std::vector<io::StatisticColumn> discretisationColumns(const std::string& observable,
                                                       const std::vector<study::StudyBar>& bars);
std::vector<std::pair<std::string, std::vector<double>>> discretisationValues(const std::string& observable,
                                                                              const std::vector<study::StudyBar>& bars);
// The precision target's columns (-ensemble_target): the half-width reached and whether it was met.
std::vector<io::StatisticColumn> targetColumns();

// The values of statisticsColumns() for every point, as ResultsFile::writeStatistics takes them;
// relative false: without _relative and _relative_ci95 (statisticsColumns(StatisticsFile::FemRun)).
struct StatisticsValues {
  std::vector<std::pair<std::string, std::vector<double>>> real;
  std::vector<std::pair<std::string, std::vector<int>>> integer;
};
StatisticsValues statisticsValues(const std::vector<PointStatistics>& statistics, bool relative = true);

}  // namespace gradfric::campaign
