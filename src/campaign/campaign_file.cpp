// The shared steps of a campaign's results file (include/gradfric/campaign/campaign_file.hpp).
#include "gradfric/campaign/campaign_file.hpp"

#include "gradfric/campaign/log_events.hpp"
#include "gradfric/campaign/resume_check.hpp"
#include "gradfric/core/collective_error.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/io/provenance.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/physics/observables.hpp"

#include <petscsys.h>

#include <set>
#include <string>
#include <utility>

namespace gradfric::campaign {

namespace {

// What an extension may change: the count (or the target) and the swept lists.
bool extensionMayChange(const std::string& name) {
  static const std::set<std::string> names = {
      "ensemble_realisations", "ensemble_delta",       "ensemble_theta",      "ensemble_sigma",
      "ensemble_property",     "ensemble_profile",     "ensemble_target",     "ensemble_target_type",
      "ensemble_target_min",   "ensemble_target_max"};
  return names.count(name) > 0;
}

// Extension: the file's points are the first points of the campaign's sweep, in order, and its
// realisations the first of each point. "" if so.
std::string extensionMismatch(const Campaign& c, const io::ResultsFile& file) {
  const auto& l = file.layout();
  if (l.points > c.points())
    return "it has " + std::to_string(l.points) + " sweep points, the scene " + std::to_string(c.points()) +
           " (an extension adds points, never removes them)";
  if (l.realisations > c.realisations)
    return "it has " + std::to_string(l.realisations) + " realisations per point, the scene " +
           std::to_string(c.realisations) + " (an extension adds realisations, never removes them)";
  const io::SweepTable& old = file.sweep();
  const io::SweepTable& now = c.table;
  // A column the layout has not (the FEM's files keep no sigma: one surface per sweep) is not compared.
  auto differs = [](const auto& a, const auto& b, int p) {
    const std::size_t i = static_cast<std::size_t>(p);
    return i < a.size() && i < b.size() && a[i] != b[i];
  };
  for (int p = 0; p < l.points; ++p)
    if (differs(old.delta, now.delta, p) || differs(old.theta, now.theta, p) || differs(old.sigma, now.sigma, p) ||
        differs(old.sigmaKinetic, now.sigmaKinetic, p) || differs(old.property, now.property, p) ||
        differs(old.profile, now.profile, p))
      return "its point " + std::to_string(p) + " is not point " + std::to_string(p) +
             " of the scene's sweep (the file's points must come first, in order: append values to the outermost "
             "swept list)";
  return "";
}

}  // namespace

io::OutputPlan planCampaignFile(MPI_Comm comm, const Campaign& c) {
  io::OutputRequest request;
  request.option = "-output";
  request.path = c.output;
  request.temporarySuffix = ".partial";
  request.overwrite = c.overwrite;
  request.overwriteOption = "-output_overwrite";
  request.resume = c.resume;
  request.resumeOption = "-resume";
  request.extend = c.extend;
  request.extendOption = "-ensemble_extend";
  return io::OutputPlan::decide(comm, request);
}

io::ResultsFile openCampaignFile(MPI_Comm comm, const Campaign& c, const io::OutputPlan& plan, const std::string& unit) {
  const ResumeTarget target{c.sceneAttributes, c.layout, "-resume", "-output_overwrite"};
  io::ResultsFile file = [&] {
    if (plan.start() == io::OutputStart::ExtendFinished) {
      Extension extension;
      extension.mayChange = extensionMayChange;
      extension.mismatch = [&c](const io::ResultsFile& old) { return extensionMismatch(c, old); };
      checkExtendable(comm, target, extension, plan.path());
      GF_CALL(PetscPrintf(comm, "Extending %s: writing %s with its %s (renamed over it when the run completes)\n",
                          plan.path().c_str(), plan.workPath().c_str(), unit.c_str()));
      io::ResultsFile extended = io::ResultsFile::create(comm, plan.workPath(), c.layout, c.table, c.sceneAttributes);
      extended.copyTasksFrom(plan.path());
      GF_CALL(PetscPrintf(comm, "%ld %s kept from %s\n", extended.finishedCount(), unit.c_str(), plan.path().c_str()));
      return extended;
    }
    if (plan.start() == io::OutputStart::Fresh) {
      GF_CALL(PetscPrintf(comm, "Writing %s (renamed to %s when the run completes)\n", plan.workPath().c_str(),
                          plan.path().c_str()));
      return io::ResultsFile::create(comm, plan.workPath(), c.layout, c.table, c.sceneAttributes);
    }
    checkResumable(comm, target, plan.workPath());
    GF_CALL(PetscPrintf(comm, "Resuming %s\n", plan.workPath().c_str()));
    io::ResultsFile resumed = io::ResultsFile::open(comm, plan.workPath());
    const long finished = resumed.finishedCount();
    GF_CALL(PetscPrintf(comm, "%ld of %d %s already finished; running the other %ld\n", finished, c.tasks(),
                        unit.c_str(), c.tasks() - finished));
    return resumed;
  }();
  try {
    file.setRun(c.runAttributes, io::collectProvenance(comm));  // and version, command line, options files, date, ranks
  } catch (const CollectiveError& e) {
    const bool resumed =
        plan.start() == io::OutputStart::ContinueTemporary || plan.start() == io::OutputStart::ContinueFinished;
    if (!resumed) {
      plan.discard(comm);  // a new file without a task: nothing to keep
      throw;
    }
    throw CollectiveError(std::string(e.what()) + "; its finished " + unit +
                          " are kept: continue with -resume once there is room");
  }
  return file;
}

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
