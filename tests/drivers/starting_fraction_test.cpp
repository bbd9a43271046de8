// The bulk fraction a run starts from, and the search for the nominal phi
// whose packing starts at a given one (drivers/starting_fraction.hpp), which
// a jam's cold start uses under sweep.cold_start_phi = "bulk".
#include "drivers/starting_fraction.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>
#include <vector>

#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_summary.hpp"
#include "io/config.hpp"

namespace dilatant::starting_fraction_test {
namespace {

Config cell(const std::vector<std::string>& extra) {
  std::vector<std::string> overrides = {"run.snapshot_interval=0"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return default_cell_config(overrides);
}

TEST(StartingFraction, IsTheBulkFractionOfTheCellARunBuilds) {
  const Config c = cell({"cell.size=[8.0, 6.0, 12.0]", "cell.phi=0.58"});
  EXPECT_DOUBLE_EQ(starting_bulk_fraction(c), bulk_fraction(ShearCell(c).state()));
  // Without walls the bulk is the box's realised fraction (whole spheres in
  // a small box: not the nominal phi), and a target it meets is met at once.
  const Config le =
      cell({"cell.boundary=\"lees-edwards\"", "cell.size=[6.0, 5.0, 7.0]", "cell.phi=0.58"});
  const double realised = ShearCell(le).state().geometry.phi_box;
  EXPECT_DOUBLE_EQ(starting_bulk_fraction(le), realised);
  const StartingFractionMatch m = match_starting_bulk(le, realised, 1e-3, 6);
  EXPECT_TRUE(m.within_tolerance);
  EXPECT_EQ(m.tried.size(), 1u);
  EXPECT_DOUBLE_EQ(m.phi, 0.58);
}

// The search's contract: the first packing measures the offset, the estimate
// and its neighbours a tolerance apart follow, it stops at the first packing
// within the tolerance, and it chooses the closest one it built.
TEST(StartingFraction, TheSearchScansAroundTheOffsetEstimateAndKeepsTheClosest) {
  constexpr double kTolerance = 1e-3;
  constexpr int kPackings = 6;
  const Config c = cell({"cell.size=[10.0, 10.0, 20.0]", "cell.phi=0.58"});
  const double target = 0.555;
  const StartingFractionMatch m = match_starting_bulk(c, target, kTolerance, kPackings);
  ASSERT_GE(m.tried.size(), 1u);
  EXPECT_DOUBLE_EQ(m.tried[0].first, 0.58);
  const double estimate = 0.58 + target - m.tried[0].second;
  const double offsets[] = {0.0, 1.0, -1.0, 2.0, -2.0};
  for (std::size_t k = 1; k < m.tried.size(); ++k)
    EXPECT_NEAR(m.tried[k].first, estimate + offsets[k - 1] * kTolerance, 1e-12) << k;
  for (std::size_t k = 0; k + 1 < m.tried.size(); ++k)  // none before the last was within
    EXPECT_GT(std::abs(m.tried[k].second - target), kTolerance) << k;
  EXPECT_TRUE(m.tried.size() == kPackings || m.within_tolerance);
  for (const auto& [phi, bulk] : m.tried)
    EXPECT_LE(std::abs(m.phi_bulk_start - target), std::abs(bulk - target)) << phi;
  EXPECT_EQ(m.within_tolerance, std::abs(m.phi_bulk_start - target) <= kTolerance);
}

// A stop request (the sweep's Ctrl-C) ends the search before the next packing.
TEST(StartingFraction, AStopRequestEndsTheSearch) {
  const Config c = cell({"cell.size=[8.0, 6.0, 12.0]", "cell.phi=0.58"});
  const std::atomic<bool> stop{true};
  const StartingFractionMatch m = match_starting_bulk(c, 0.5, 1e-3, 6, &stop);
  EXPECT_TRUE(m.tried.empty());
  EXPECT_FALSE(m.within_tolerance);
}

}  // namespace
}  // namespace dilatant::starting_fraction_test
