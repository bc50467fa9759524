// One evaluation of a design problem (include/gradfric/design/evaluator.hpp).
#include "gradfric/design/evaluator.hpp"

#include "gradfric/physics/observables.hpp"

#include "gradfric/campaign/precision_target.hpp"
#include "gradfric/campaign/realisation_pool.hpp"
#include "gradfric/sbm/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gradfric::design {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The ensemble's statistics of the first n realisations of each plate (P x n tables).
std::vector<campaign::PointStatistics> statisticsOf(const std::vector<const std::vector<double>*>& plates, int n,
                                                    const std::vector<int>& reference, bool paired) {
  std::vector<double> muStatic;
  for (const auto* values : plates) muStatic.insert(muStatic.end(), values->begin(), values->begin() + n);
  // A design measures mu_s alone (every other observable NaN).
  std::vector<std::vector<double>> tables(statisticsObservables().size(), std::vector<double>(muStatic.size(), kNaN));
  tables[statisticsIndex("mu_s")] = muStatic;
  const std::vector<signed char> confirmed(muStatic.size(), 1);
  const std::vector<unsigned char> done(muStatic.size(), 1);
  return campaign::pointStatistics(n, reference, tables, confirmed, done, paired);
}

}  // namespace

Evaluator::Evaluator(MPI_Comm comm, const Problem& problem) : comm_(comm), problem_(problem) {}

void Evaluator::run(const std::vector<Batch>& batches) {
  struct Task {
    int batch, realisation;
  };
  std::vector<Task> tasks;
  for (int b = 0; b < static_cast<int>(batches.size()); ++b)
    for (int r = static_cast<int>(batches[b].sink->size()); r < batches[b].count; ++r) tasks.push_back({b, r});
  campaign::PoolPlan plan;
  plan.tasks = static_cast<long>(tasks.size());
  plan.width = 2;  // mu_s, wall seconds
  plan.failure = [&](long k, int rank, const std::string& what) {
    const Batch& b = batches[tasks[k].batch];
    return "realisation " + std::to_string(tasks[k].realisation) + " at " +
           (b.x ? problem_.describe(*b.x) : std::string("the non-graded plate")) + " failed on rank " +
           std::to_string(rank) + ": " + what;
  };
  const std::vector<double> records = campaign::runRealisationPool(comm_, plan, [&](long k) {
    const Batch& b = batches[tasks[k].batch];
    const Grading grading = b.x ? problem_.gradingAt(*b.x) : problem_.referenceGrading();
    const sbm::Result result = sbm::simulate(problem_.parameters, grading, problem_.request,
                                             StreamKey{problem_.seed, b.stream, static_cast<std::uint32_t>(tasks[k].realisation)});
    return std::vector<double>{result.friction.muStatic, result.wallSeconds};
  });
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    batches[tasks[k].batch].sink->push_back(records[2 * k]);  // in order
    taskSeconds_ += records[2 * k + 1];
  }
  realisations_ += static_cast<long>(tasks.size());
}

Evaluation Evaluator::evaluate(const std::vector<double>& x, double halfWidth, const std::string& phase,
                               std::uint32_t stream, int atLeast) {
  std::vector<double>& mine = values_[{stream, x}];
  std::vector<double>& reference = reference_[stream];
  const bool variation = problem_.kind == TargetKind::Variation;
  campaign::PrecisionTarget target;
  target.kind = variation ? campaign::TargetKind::Variation : campaign::TargetKind::Absolute;
  target.halfWidth = halfWidth;
  target.first = problem_.firstBatch;
  target.cap = problem_.cap;
  // Points of the plan: the reference (paired) and x, or x alone.
  const std::vector<int> referenceOf = variation ? std::vector<int>{0, 0} : std::vector<int>{-1};
  const std::vector<const std::vector<double>*> plates =
      variation ? std::vector<const std::vector<double>*>{&reference, &mine} : std::vector<const std::vector<double>*>{&mine};
  int n = std::min(problem_.cap, std::max({problem_.firstBatch, static_cast<int>(mine.size()), atLeast}));
  std::vector<campaign::PointStatistics> statistics;
  for (;;) {
    std::vector<Batch> batches;
    if (variation) batches.push_back({nullptr, stream, n, &reference});
    batches.push_back({&x, stream, n, &mine});
    run(batches);
    statistics = statisticsOf(plates, n, referenceOf, variation);
    const std::vector<int> counts(plates.size(), n);
    const std::vector<int> next = campaign::planNextBatch(target, counts, statistics, referenceOf);
    if (next == counts) break;
    n = *std::max_element(next.begin(), next.end());
  }
  const int p = variation ? 1 : 0;
  Evaluation e;
  e.index = count_++;
  e.phase = phase;
  e.x = x;
  e.realisations = n;
  const std::size_t mu = statisticsIndex("mu_s");
  e.muStatic = statistics[p].observables[mu].summary.mean;
  e.muStaticCiLow = statistics[p].observables[mu].summary.ciLow;
  e.muStaticCiHigh = statistics[p].observables[mu].summary.ciHigh;
  if (variation) {
    const double h = campaign::achievedHalfWidth(target, statistics, referenceOf, 1);
    e.value = statistics[1].observables[mu].relative.value;
    e.ciLow = e.value - h;
    e.ciHigh = e.value + h;
  } else {
    e.value = e.muStatic;
    e.ciLow = e.muStaticCiLow;
    e.ciHigh = e.muStaticCiHigh;
  }
  return e;
}

}  // namespace gradfric::design
