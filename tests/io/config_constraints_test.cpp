// Keys that constrain each other name the key the user wrote, not the built-in
// default cell's own line (issue 31: "some bounds name the wrong limit").
#include <gtest/gtest.h>

#include <string>

#include "io/config.hpp"
#include "io/input_error.hpp"

namespace dilatant::io::config_constraints_test {
namespace {

std::string message_of(const std::vector<std::string>& overrides) {
  try {
    default_cell_config(overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ConfigConstraints, AnOverrideOfTheBuiltInCellIsTheKeyBlamed) {
  // The built-in cell writes run.strain = 12 and run.transient_strain = 6
  // itself: the user's run.strain is the key at fault.
  EXPECT_EQ(message_of({"run.strain=0"}),
            "--set run.strain = 0: must be > run.transient_strain = 6");
  EXPECT_EQ(message_of({"run.transient_strain=20"}),
            "--set run.transient_strain = 20: must be < run.strain = 12");
  EXPECT_EQ(message_of({"cell.radius_min=1.5"}),
            "--set cell.radius_min = 1.5: must be <= cell.radius_max = 1");
  EXPECT_EQ(message_of({"cell.radius_max=0.5"}),
            "--set cell.radius_max = 0.5: must be >= cell.radius_min = 0.8");
}

}  // namespace
}  // namespace dilatant::io::config_constraints_test
