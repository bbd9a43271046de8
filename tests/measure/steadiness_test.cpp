// The drift test of the averaging window (measure/steadiness.hpp) on synthetic
// time series whose answer is known.
#include "measure/steadiness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace dilatant::steadiness_test {
namespace {

// Rows of 0.05 strain each from strain 0, wall speed speed(strain) + noise.
template <class Speed>
std::vector<FlowRow> series(int n, Speed speed, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  std::vector<FlowRow> rows;
  for (int k = 1; k <= n; ++k) {
    FlowRow r;
    r.strain = 0.05 * k;
    r.duration = 1.0;
    r.wall_velocity = speed(r.strain) + gauss(rng);
    rows.push_back(r);
  }
  return rows;
}

TEST(Steadiness, ConstantSpeedWithNoiseIsSteady) {
  // 3-sigma test: of 200 independent noisy series at most a few may be flagged.
  int flagged = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Drift d = wall_speed_drift(series(
                                         160, [](double) { return 2.0; }, 0.5, seed),
                                     2.0);
    ASSERT_TRUE(d.known);
    flagged += d.steady ? 0 : 1;
  }
  EXPECT_LE(flagged, 4);  // expected 200 x P(|z| > 3) ~ 0.5, or a 5% change at 0.13 sigma
}

TEST(Steadiness, AcceleratingWallIsNotSteady) {
  // Speed up 20% over the window (strain 2 to 8), little noise: the halves'
  // means differ by about 10% of the mean, far above 3 sigma and 5%.
  const Drift d =
      wall_speed_drift(series(
                           160, [](double g) { return 1.0 + 0.2 * (g - 2.0) / 6.0; }, 0.01, 7),
                       2.0);
  ASSERT_TRUE(d.known);
  EXPECT_FALSE(d.steady);
  EXPECT_NEAR(d.change, 0.1 / 1.1, 0.01);
}

TEST(Steadiness, SmallDriftWithinFivePercentIsSteady) {
  const Drift d =
      wall_speed_drift(series(
                           160, [](double g) { return 1.0 + 0.04 * (g - 2.0) / 6.0; }, 0.0, 1),
                       2.0);
  ASSERT_TRUE(d.known);
  EXPECT_TRUE(d.steady);
}

TEST(Steadiness, ShortWindowIsUnknown) {
  const Drift d = wall_speed_drift(series(
                                       60, [](double) { return 1.0; }, 0.1, 3),
                                   2.0);
  EXPECT_FALSE(d.known);  // 20 rows after the transient: 10 per half, fewer than 2 x kBlocks
}

// phi_bulk under pressure control: a box still growing (phi from 0.57 to 0.51
// over the window) drifts; a steady one with noise does not, nor a drift
// below the 1% floor.
TEST(Steadiness, AGrowingBoxIsNotSteady) {
  const auto rows_of = [](double phi_start, double phi_end, double noise) {
    std::vector<FlowRow> rows = series(
        160, [](double) { return 1.0; }, 0.0, 1);
    std::mt19937 rng(5);
    std::normal_distribution<double> gauss(0.0, noise);
    for (FlowRow& r : rows)
      r.phi_bulk = phi_start + (phi_end - phi_start) * (r.strain - 2.0) / 6.0 + gauss(rng);
    return rows;
  };
  const Drift growing = volume_fraction_drift(rows_of(0.57, 0.51, 0.002), 2.0);
  ASSERT_TRUE(growing.known);
  EXPECT_FALSE(growing.steady);
  EXPECT_LT(growing.change, 0.0);
  const Drift steady = volume_fraction_drift(rows_of(0.57, 0.57, 0.002), 2.0);
  ASSERT_TRUE(steady.known);
  EXPECT_TRUE(steady.steady);
  EXPECT_TRUE(volume_fraction_drift(rows_of(0.57, 0.566, 0.0), 2.0).steady);  // 0.35%
  EXPECT_TRUE(wall_speed_drift(rows_of(0.57, 0.51, 0.0), 2.0).steady);  // the speed is constant
}

}  // namespace
}  // namespace dilatant::steadiness_test
