// The shared steps of a campaign's results file (include/gradfric/campaign/campaign_file.hpp).
#include "gradfric/campaign/campaign_file.hpp"

#include "gradfric/campaign/log_events.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/physics/observables.hpp"

#include <string>
#include <utility>

namespace gradfric::campaign {

std::vector<std::vector<double>> observableTables(const io::ResultsFile& file) {
  std::vector<std::vector<double>> tables;
  for (const Observable& o : statisticsObservables()) tables.push_back(file.readRealisationReal(o.name));
  return tables;
}

std::vector<PointStatistics> writeStatistics(io::ResultsFile& file, int realisations, const std::vector<int>& reference,
                                             bool commonStreams, const PrecisionTarget* target) {
  // Every rank reads the small P x R tables and computes the same numbers; rank 0 writes them.
  const LogEventScope timed(logEvents().statistics);
  const auto flags = file.finishedTasks();
  const std::vector<unsigned char> done(flags.begin(), flags.end());
  const auto stats = pointStatistics(realisations, reference, observableTables(file), file.readPeakConfirmed(), done,
                                     commonStreams);
  // A single FEM run's file has no reference point and no relative columns (statisticsColumns).
  auto [real, integer] = statisticsValues(stats, !file.layout().singleRun());
  if (target) {  // the half-width each point reached and whether it met the target
    std::vector<double> reached;
    std::vector<int> met;
    for (int p = 0; p < static_cast<int>(reference.size()); ++p) {
      reached.push_back(achievedHalfWidth(*target, stats, reference, p));
      met.push_back(reached.back() <= target->halfWidth ? 1 : 0);
    }
    real.emplace_back("target_half_width", reached);
    integer.emplace_back("target_met", met);
  }
  file.writeStatistics(real, integer);
  return stats;
}

void finishResultsFile(MPI_Comm comm, io::ResultsFile& file, const io::OutputPlan& plan) {
  {
    const LogEventScope timed(logEvents().write);
    file.markCompleteAndClose();
  }
  plan.commit(comm);
}

}  // namespace gradfric::campaign
