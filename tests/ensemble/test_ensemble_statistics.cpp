// Statistics of a sweep point: exact values for small samples, Student t quantiles against
// tables, the relative variation and its propagated error.
#include "gradfric/campaign/statistics.hpp"
#include "gradfric/campaign/statistics_columns.hpp"
#include "gradfric/physics/observables.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace gradfric::campaign;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
}

TEST(EnsembleStatistics, StudentQuantilesMatchTables) {
  // Two-sided 95 % critical values (tables of the t distribution).
  EXPECT_NEAR(studentTQuantile(0.975, 1), 12.7062047, 1e-6);
  EXPECT_NEAR(studentTQuantile(0.975, 2), 4.30265273, 1e-7);
  EXPECT_NEAR(studentTQuantile(0.975, 4), 2.77644511, 1e-7);
  EXPECT_NEAR(studentTQuantile(0.975, 19), 2.09302405, 1e-7);
  EXPECT_NEAR(studentTQuantile(0.975, 1000), 1.96233908, 1e-7);
  EXPECT_NEAR(studentTQuantile(0.025, 19), -2.09302405, 1e-7);
  EXPECT_NEAR(studentTQuantile(0.995, 10), 3.16927267, 1e-7);
  EXPECT_DOUBLE_EQ(studentTQuantile(0.5, 3), 0.0);
}

TEST(EnsembleStatistics, IncompleteBetaKnownValues) {
  EXPECT_NEAR(incompleteBeta(1.0, 1.0, 0.3), 0.3, 1e-14);                        // uniform
  EXPECT_NEAR(incompleteBeta(2.0, 3.0, 0.4), 0.5248, 1e-12);                    // polynomial case
  EXPECT_NEAR(incompleteBeta(0.5, 0.5, 0.5), 0.5, 1e-12);                       // symmetric
  const double x = 0.9, a = 5.0, b = 2.0;  // I_x(5,2) = x^5 (6 - 5x)
  EXPECT_NEAR(incompleteBeta(a, b, x), std::pow(x, 5) * (6 - 5 * x), 1e-12);
}

TEST(EnsembleStatistics, SummaryOfASmallSample) {
  const Summary s = summarise({0.9, 1.0, 1.1, 1.0});
  EXPECT_EQ(s.count, 4);
  EXPECT_NEAR(s.mean, 1.0, 1e-15);
  const double sd = std::sqrt(0.02 / 3.0);
  EXPECT_NEAR(s.stdDev, sd, 1e-15);
  EXPECT_NEAR(s.stdError, sd / 2.0, 1e-15);
  const double t = 3.18244631;  // t(0.975, 3)
  EXPECT_NEAR(s.ciLow, 1.0 - t * sd / 2.0, 1e-8);
  EXPECT_NEAR(s.ciHigh, 1.0 + t * sd / 2.0, 1e-8);
}

TEST(EnsembleStatistics, NaNEntriesAreSkippedAndSmallSamplesHaveNoSpread) {
  const Summary s = summarise({kNaN, 2.0, kNaN, 4.0});
  EXPECT_EQ(s.count, 2);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_NEAR(s.stdDev, std::sqrt(2.0), 1e-15);
  const Summary one = summarise({0.7});
  EXPECT_EQ(one.count, 1);
  EXPECT_DOUBLE_EQ(one.mean, 0.7);
  EXPECT_TRUE(std::isnan(one.stdDev));
  EXPECT_TRUE(std::isnan(one.ciLow));
  const Summary none = summarise({kNaN});
  EXPECT_EQ(none.count, 0);
  EXPECT_TRUE(std::isnan(none.mean));
}

TEST(EnsembleStatistics, NoCancellationForCloseValues) {
  // Values 1 +- 1e-9: a one-pass sum of squares would lose the spread entirely.
  const Summary s = summarise({1.0 + 1e-9, 1.0 - 1e-9, 1.0 + 1e-9, 1.0 - 1e-9});
  EXPECT_NEAR(s.stdDev, 1e-9 * std::sqrt(4.0 / 3.0), 1e-15);
}

TEST(EnsembleStatistics, RelativeVariationAndPropagatedError) {
  Summary ref;
  ref.count = 10;
  ref.mean = 0.95;
  ref.stdError = 0.002;
  Summary point;
  point.count = 10;
  point.mean = 0.76;
  point.stdError = 0.003;
  const RelativeVariation v = relativeVariation(point, ref, false);
  EXPECT_NEAR(v.value, (0.76 - 0.95) / 0.95, 1e-15);
  const double expected = std::hypot(0.003 / 0.95, 0.76 * 0.002 / (0.95 * 0.95));
  EXPECT_NEAR(v.error, expected, 1e-15);
  // The printed and stored interval: 95 % Student t with the smaller sample's n - 1 = 5 dof.
  point.count = 6;
  EXPECT_NEAR(relativeVariation(point, ref, false).halfWidth, 2.57058184 * expected, 1e-9);
  const RelativeVariation self = relativeVariation(ref, ref, true);
  EXPECT_EQ(self.value, 0.0);
  EXPECT_EQ(self.error, 0.0);
  EXPECT_EQ(self.halfWidth, 0.0);
}

TEST(EnsembleStatistics, PointTableCountsOnlyFinishedRealisations) {
  // 2 points x 3 realisations; point 0 is the reference of both.
  const std::vector<double> muS = {1.0, 0.9, 100.0, 0.8, 0.7, 0.6};
  const std::vector<double> muK = {0.6, 0.6, 100.0, kNaN, 0.5, 0.7};
  const std::vector<signed char> confirmed = {1, 1, 1, 1, 0, 1};
  const std::vector<unsigned char> done = {1, 1, 0, 1, 1, 1};  // (0, 2) not finished: its 100 must not count
  const auto stats = pointStatistics(3, {0, 0}, {muS, muK}, confirmed, done);
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].finished, 2);
  EXPECT_NEAR(stats[0].observables[0].summary.mean, 0.95, 1e-15);
  EXPECT_NEAR(stats[0].observables[1].summary.mean, 0.6, 1e-15);
  EXPECT_EQ(stats[1].finished, 3);
  EXPECT_EQ(stats[1].peaksUnconfirmed, 1);
  EXPECT_NEAR(stats[1].observables[0].summary.mean, 0.7, 1e-15);
  EXPECT_EQ(stats[1].observables[1].summary.count, 2);  // the NaN mu_k is skipped
  EXPECT_NEAR(stats[1].observables[1].summary.mean, 0.6, 1e-15);
  EXPECT_EQ(stats[0].observables[0].relative.value, 0.0);
  EXPECT_NEAR(stats[1].observables[0].relative.value, (0.7 - 0.95) / 0.95, 1e-15);
  EXPECT_GT(stats[1].observables[0].relative.error, 0.0);
  const auto orphan = pointStatistics(3, {-1, -1}, {muS, muK}, confirmed, done);
  EXPECT_TRUE(std::isnan(orphan[1].observables[0].relative.value));
  EXPECT_THROW(pointStatistics(2, {0, 0}, {muS, muK}, confirmed, done), std::invalid_argument);
}

TEST(EnsembleStatistics, PairedRelativeVariation) {
  // The point is exactly 0.8 x its reference realisation by realisation: the ratio is known
  // without error from the pairs, while the independent formula sees both spreads.
  const std::vector<double> y = {0.90, 0.93, 0.91, 0.95, 0.92};
  std::vector<double> x;
  for (double v : y) x.push_back(0.8 * v);
  const RelativeVariation paired = pairedRelativeVariation(x, y);
  EXPECT_NEAR(paired.value, -0.2, 1e-14);
  EXPECT_LT(paired.error, 1e-14);
  const RelativeVariation independent = relativeVariation(summarise(x), summarise(y), false);
  EXPECT_NEAR(independent.value, -0.2, 1e-14);
  EXPECT_GT(independent.error, 1e-3);
  // Uncorrelated noise on top: the paired error is the standard error of z_r.
  const std::vector<double> noisy = {0.72, 0.75, 0.73, 0.74, 0.76};
  const RelativeVariation p2 = pairedRelativeVariation(noisy, y);
  const double m = summarise(noisy).mean, m0 = summarise(y).mean;
  std::vector<double> z;
  for (size_t i = 0; i < y.size(); ++i) z.push_back(noisy[i] / m0 - m * y[i] / (m0 * m0));
  EXPECT_NEAR(p2.error, summarise(z).stdError, 1e-15);
  EXPECT_NEAR(p2.halfWidth, 2.77644511 * p2.error, 1e-9);  // t(0.975, 5 pairs - 1)
  // Pairs with a NaN on either side are dropped; fewer than two pairs: no error estimate.
  const RelativeVariation p3 = pairedRelativeVariation({0.8, kNaN, 0.7}, {1.0, 1.0, kNaN});
  EXPECT_NEAR(p3.value, -0.2, 1e-15);
  EXPECT_TRUE(std::isnan(p3.error));
  EXPECT_TRUE(std::isnan(p3.halfWidth));
}

TEST(EnsembleStatistics, PointTableUsesPairsWhenAsked) {
  // Point 1 = 0.8 x point 0 realisation by realisation; realisation 2 of point 0 unfinished.
  const std::vector<double> muS = {1.0, 0.9, 0.95, 0.8, 0.72, 0.76};
  const std::vector<double> muK = {0.6, 0.6, 0.6, 0.48, 0.48, 0.48};
  const std::vector<signed char> confirmed(6, 1);
  const std::vector<unsigned char> done = {1, 1, 0, 1, 1, 1};
  const auto paired = pointStatistics(3, {0, 0}, {muS, muK}, confirmed, done, true);
  EXPECT_NEAR(paired[1].observables[0].relative.value, -0.2, 1e-14);  // over the common pairs 0 and 1
  EXPECT_LT(paired[1].observables[0].relative.error, 1e-14);
  EXPECT_EQ(paired[0].observables[0].relative.value, 0.0);
  const auto independent = pointStatistics(3, {0, 0}, {muS, muK}, confirmed, done, false);
  EXPECT_GT(independent[1].observables[0].relative.error, 1e-3);
}

TEST(EnsembleStatistics, ColumnsComeFromTheObservableTable) {
  // finished, then each observable with statistics (physics/observables.hpp: mu_s and mu_k first,
  // then the rows added since) with its seven real columns and its count, then peaks_unconfirmed.
  std::vector<std::string> names;
  for (const auto& c : statisticsColumns()) names.push_back(c.name + (c.integer ? ":int" : ""));
  const std::vector<gradfric::Observable> rows = gradfric::statisticsObservables();
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[0].name, "mu_s");
  EXPECT_EQ(rows[1].name, "mu_k");
  std::vector<std::string> expected = {"finished:int"};
  for (const auto& row : rows) {
    for (const char* s : {"_mean", "_std", "_stderr", "_ci95_low", "_ci95_high", "_relative", "_relative_ci95"})
      expected.push_back(row.name + s);
    expected.push_back(row.name + "_count:int");
  }
  expected.push_back("peaks_unconfirmed:int");
  EXPECT_EQ(names, expected);
  const auto columns = statisticsColumns();
  EXPECT_EQ(columns[14].description, "(mu_k - mu_k_0) / mu_k_0 against /sweep/reference_point");
  ASSERT_EQ(columns[4].attributes.size(), 1u);  // mu_s_ci95_low: an interval
  EXPECT_EQ(columns[4].attributes[0].second, "95 % Student t, n - 1 degrees of freedom");
  // The values line up with the names: one table per observable with statistics, mu_s and mu_k
  // given, the others NaN.
  std::vector<std::vector<double>> tables(rows.size(), {kNaN, kNaN});
  tables[0] = {1.0, 0.9};
  tables[1] = {0.6, kNaN};
  const auto stats = pointStatistics(2, {0}, tables, {1, 1}, {1, 1});
  const StatisticsValues values = statisticsValues(stats);
  auto real = [&](const std::string& name) {
    for (const auto& [n, v] : values.real)
      if (n == name) return v.at(0);
    return -1.0;
  };
  auto integer = [&](const std::string& name) {
    for (const auto& [n, v] : values.integer)
      if (n == name) return v.at(0);
    return -1;
  };
  EXPECT_NEAR(real("mu_s_mean"), 0.95, 1e-15);
  EXPECT_EQ(real("mu_k_mean"), 0.6);
  EXPECT_EQ(integer("mu_k_count"), 1);
  EXPECT_EQ(integer("finished"), 2);
  EXPECT_EQ(values.real.size() + values.integer.size(), columns.size());
}

TEST(EnsembleStatistics, ASingleFemRunHasNoRelativeColumns) {
  // One run has no reference point: its file's columns and values lack _relative and
  // _relative_ci95 alike, and name the FEM's run length; a FEM sweep keeps the ensemble's columns.
  std::vector<std::string> names, values, sweep, ensemble;
  for (const auto& c : statisticsColumns(StatisticsFile::FemRun)) names.push_back(c.name);
  for (const auto& c : statisticsColumns(StatisticsFile::FemSweep)) sweep.push_back(c.name);
  for (const auto& c : statisticsColumns()) ensemble.push_back(c.name);
  EXPECT_EQ(sweep, ensemble);
  for (const auto& name : names) EXPECT_EQ(name.find("_relative"), std::string::npos) << name;
  EXPECT_EQ(names.size() + 2 * gradfric::statisticsObservables().size(), ensemble.size());
  const std::vector<gradfric::Observable> rows = gradfric::statisticsObservables();
  std::vector<std::vector<double>> tables(rows.size(), {kNaN});
  tables[0] = {0.9};
  const StatisticsValues written = statisticsValues(pointStatistics(1, {-1}, tables, {1}, {1}), false);
  for (const auto& [name, v] : written.real) values.push_back(name);
  for (const auto& [name, v] : written.integer) values.push_back(name);
  std::sort(values.begin(), values.end());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(values, names);
  EXPECT_EQ(statisticsColumns(StatisticsFile::FemRun).back().description,
            "realisations whose peak was not confirmed before the run ended (-fem_slide_time)");
}
