// A jammed cell still reports its packing: dry grains with friction 1 in a small
// cell well above their shear-jamming fraction (about 0.58 at mu 1, Chialvo, Sun
// & Sundaresan 2012) stop the wall before the transient ends, so no steady row
// exists; the bulk fraction then comes from the final state. A jammed frictional
// packing of hard spheres lies between random loose packing (about 0.55) and
// random close packing (about 0.64; our 0.8-1.0 R polydispersity packs a little
// denser, hence 0.66).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "drivers/cell_run_helpers.hpp"

namespace dilatant::shear_cell_jam_test {
namespace {

nlohmann::json jammed_cell(const std::string& transient) {
  return test::run_cell_summary(
      "jam", {"cell.size=[8.0, 5.0, 9.0]", "cell.phi=0.62", "friction.law=coulomb",
              "friction.mu0=1.0", "run.strain=2.0", "run.transient_strain=" + transient,
              "run.snapshot_interval=0.0", "fluid.lubrication=none", "fluid.drag=none"});
}

TEST(CellJam, AJammedRunReportsTheBulkFractionOfItsPacking) {
  const auto j = jammed_cell("1.0");
  ASSERT_TRUE(j["jammed"].get<bool>());
  EXPECT_FALSE(j["valid"].get<bool>());
  ASSERT_FALSE(j["invalid_reasons"].empty());
  EXPECT_EQ(j["invalid_reasons"][0].get<std::string>().rfind("jammed", 0), 0u);
  EXPECT_TRUE(j["eta"].is_null());
  const double phi_bulk = j["phi_bulk"].get<double>();
  EXPECT_GT(phi_bulk, 0.55);
  EXPECT_LT(phi_bulk, 0.66);
  EXPECT_TRUE(j["phi_bulk_err"].is_null());  // one state, no average
}

// Jammed after the transient: the rows are averaged, and the last one (closed
// when the run stops, holding the jam's waiting time) carries its bulk
// fraction too. It once did not, and a jammed packing at 0.57 reported 0.014.
TEST(CellJam, TheLastRowOfAJammedRunCountsItsBulkFraction) {
  const auto j = jammed_cell("0.0");
  ASSERT_TRUE(j["jammed"].get<bool>());
  const double phi_bulk = j["phi_bulk"].get<double>();
  EXPECT_GT(phi_bulk, 0.55);
  EXPECT_LT(phi_bulk, 0.66);
}

}  // namespace
}  // namespace dilatant::shear_cell_jam_test
