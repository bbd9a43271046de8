// Steady-state averages and their block errors (measure/flow_series.hpp), on
// synthetic series whose mean and standard error are known in closed form.
#include "measure/flow_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace dilatant::flow_series_test {
namespace {

// Rows of equal duration 0.25 (exact in binary, so blocks split exactly),
// 0.05 strain apart, carrying x in wall_velocity.
std::vector<FlowRow> rows_of(const std::vector<double>& x) {
  std::vector<FlowRow> rows;
  for (std::size_t k = 0; k < x.size(); ++k) {
    FlowRow r;
    r.strain = 0.05 * double(k + 1);
    r.duration = 0.25;
    r.wall_velocity = x[k];
    rows.push_back(r);
  }
  return rows;
}

SteadyAverage average(const std::vector<FlowRow>& rows, double from = 0.0) {
  return steady_average(rows, from, [](const FlowRow& r) { return r.wall_velocity; });
}

// x_t = a x_{t-1} + e_t, e ~ N(0, 1): stationary variance 1/(1 - a^2) and, for
// N >> 1/(1 - a), Var(mean) = Var(x)/N (1 + a)/(1 - a).
std::vector<double> ar1(double a, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, 1.0);
  std::vector<double> x(static_cast<std::size_t>(n));
  double prev = e(rng) / std::sqrt(1.0 - a * a);  // start in the stationary state
  for (double& v : x) v = prev = a * prev + e(rng);
  return x;
}

// The mean ratio of the block error to `truth` over `series` AR(1) series of n
// rows. The rows are built once and only their x rewritten per series (a row is
// some 50 fields: building 200 x 20000 of them cost most of the test's time).
double mean_error_ratio(double a, int n, int series, std::uint64_t first_seed, double truth) {
  std::vector<FlowRow> rows = rows_of(std::vector<double>(static_cast<std::size_t>(n), 0.0));
  double ratio_sum = 0.0;
  for (int s = 0; s < series; ++s) {
    const std::vector<double> x = ar1(a, n, first_seed + static_cast<std::uint64_t>(s));
    for (std::size_t k = 0; k < x.size(); ++k) rows[k].wall_velocity = x[k];
    const SteadyAverage m = average(rows);
    EXPECT_EQ(m.samples, n);
    ratio_sum += m.error / truth;
  }
  return ratio_sum / series;
}

// The block error estimates the true standard error of the mean of a
// correlated series. With B = kBlocks blocks the estimate itself scatters by
// ~1/sqrt(2 (B - 1)) = 24% relative; over 200 independent series its mean
// ratio to the truth must lie within 4 of its own standard errors (4 x 24% /
// sqrt(200) = 6.7%), and blocks of 2000 samples >> the correlation time
// (1 + a)/(1 - a) = 19 keep the bias below that.
TEST(SteadyAverage, BlockErrorMatchesTheStandardErrorOfACorrelatedSeries) {
  const double a = 0.9;
  const int n = 20000, series = 200;
  const double truth = std::sqrt(1.0 / (1.0 - a * a) / n * (1.0 + a) / (1.0 - a));
  const double scatter = 1.0 / std::sqrt(2.0 * (kBlocks - 1)) / std::sqrt(double(series));
  EXPECT_NEAR(mean_error_ratio(a, n, series, 1000, truth), 1.0, 4.0 * scatter);
}

// Independent samples: the error is sigma/sqrt(N); an estimate that ignored the
// blocks would be this for the AR(1) series too, sqrt(19) times too small.
TEST(SteadyAverage, IndependentSamplesGiveSigmaOverRootN) {
  const int n = 20000, series = 200;
  const double scatter = 1.0 / std::sqrt(2.0 * (kBlocks - 1)) / std::sqrt(double(series));
  EXPECT_NEAR(mean_error_ratio(0.0, n, series, 7, 1.0 / std::sqrt(double(n))), 1.0, 4.0 * scatter);
}

TEST(SteadyAverage, ExcludesTheTransientAndWeighsByDuration) {
  std::vector<double> x(40, 1.0);
  for (int k = 0; k < 10; ++k) x[static_cast<std::size_t>(k)] = 100.0;  // strain <= 0.5
  const SteadyAverage m = average(rows_of(x), 0.5);
  EXPECT_EQ(m.samples, 30);
  EXPECT_DOUBLE_EQ(m.mean, 1.0);
  // Duration weighting: a row twice as long counts twice.
  auto rows = rows_of({1.0, 4.0});
  rows[1].duration = 0.5;
  EXPECT_DOUBLE_EQ(average(rows).mean, (1.0 * 0.25 + 4.0 * 0.5) / 0.75);
}

// Fewer than 2 rows per block: a mean, but no error bar (0 means unknown).
TEST(SteadyAverage, TooShortASeriesHasNoErrorBar) {
  const SteadyAverage m = average(rows_of(std::vector<double>(2 * kBlocks - 1, 3.0)));
  EXPECT_EQ(m.samples, 2 * kBlocks - 1);
  EXPECT_DOUBLE_EQ(m.mean, 3.0);
  EXPECT_EQ(m.error, 0.0);
  EXPECT_EQ(average({}).samples, 0);
}

// One output interval: time averages of the per-step sums.
TEST(IntervalSums, CloseTurnsSumsIntoTimeAverages) {
  IntervalSums a;
  a.time = 2.0;
  a.velocity = 6.0;  // mean V = 3
  a.closed = 10.0;   // time-weighted contact counts
  a.boundary = 4.0;  // 40% BL
  a.impulsive = 5.0;
  a.impulsive_boundary = 3.0;
  a.steps = 4.0;
  a.iterations = 100.0;
  a.work_drive = 8.0;
  a.kinetic_start = 1.0;
  a.kinetic_end = 5.0;
  const FlowRow r = a.close(7.0, 0.5);
  EXPECT_DOUBLE_EQ(r.wall_velocity, 3.0);
  EXPECT_DOUBLE_EQ(r.frac_bl, 0.4);
  EXPECT_DOUBLE_EQ(r.frac_impulsive, 0.5);
  EXPECT_DOUBLE_EQ(r.frac_bl_persistent, (4.0 - 3.0) / (10.0 - 5.0));
  EXPECT_DOUBLE_EQ(r.mean_iterations, 25.0);
  EXPECT_DOUBLE_EQ(r.mean_dt, 0.5);
  EXPECT_DOUBLE_EQ(r.power_drive, 4.0);
  EXPECT_DOUBLE_EQ(r.power_kinetic, 2.0);
  EXPECT_EQ(IntervalSums{}.close(1.0, 0.1).duration, 0.0);
}

}  // namespace
}  // namespace dilatant::flow_series_test
