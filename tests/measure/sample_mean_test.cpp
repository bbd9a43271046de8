// The mean of repeated measurements and its standard error
// (measure/sample_mean.hpp), against values worked out by hand.
#include "measure/sample_mean.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace dilatant::sample_mean_test {
namespace {

// {1, 2, 3, 4}: mean 5/2, squared deviations 9/4 + 1/4 + 1/4 + 9/4 = 5, so
// sd = sqrt(5 / 3) (n - 1 = 3) and sem = sd / sqrt(4).
TEST(SampleMean, FourValuesGiveBesselsDeviationAndItsStandardError) {
  const std::vector<double> x{1.0, 2.0, 3.0, 4.0};
  const SampleMean m = sample_mean(x);
  EXPECT_EQ(m.n, 4u);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.sd, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(m.sem, std::sqrt(5.0 / 3.0) / 2.0);
}

// A spread cannot be measured from one value, nor a mean from none: NaN, not 0,
// so that no caller mistakes "unknown" for "exact".
TEST(SampleMean, OneValueHasNoSpreadAndNoneHasNoMean) {
  const std::vector<double> one{0.6355};
  const SampleMean m = sample_mean(one);
  EXPECT_EQ(m.n, 1u);
  EXPECT_DOUBLE_EQ(m.mean, 0.6355);
  EXPECT_TRUE(std::isnan(m.sd));
  EXPECT_TRUE(std::isnan(m.sem));
  const SampleMean none = sample_mean({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_TRUE(std::isnan(none.mean));
}

// Deviations taken from the mean: an offset of 1e8 leaves {1, 2, 3}'s sd of 1
// intact (sum(v^2) - n mean^2 would lose it to rounding).
TEST(SampleMean, ALargeOffsetDoesNotCancelTheSpread) {
  const std::vector<double> x{1e8 + 1.0, 1e8 + 2.0, 1e8 + 3.0};
  const SampleMean m = sample_mean(x);
  EXPECT_DOUBLE_EQ(m.mean, 1e8 + 2.0);
  EXPECT_NEAR(m.sd, 1.0, 1e-12);
}

}  // namespace
}  // namespace dilatant::sample_mean_test
