// A cell's set-up reports its progress and stops at a stop request
// (drivers/setup_monitor.hpp): what keeps a large or mistyped cell from a
// silent set-up that Ctrl-C cannot stop.
#include "drivers/setup_monitor.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"

namespace dilatant::drivers::setup_monitor_test {
namespace {

Config cell() {
  return default_cell_config(
      {"cell.size=[8.0, 6.0, 9.0]", "run.strain=0.01", "run.transient_strain=0.005"});
}

TEST(SetupMonitor, TheGrowthReportsARisingFractionUpToOne) {
  std::vector<double> seen;
  std::vector<std::string> stages;
  {
    const ScopedSetupMonitor monitor({.progress = [&](std::string_view stage, double f) {
      seen.push_back(f);
      stages.emplace_back(stage);
    }});
    const ShearCell built(cell());
    EXPECT_GT(built.state().world.bodies.size(), 0u);
  }
  ASSERT_GT(seen.size(), 3u);
  EXPECT_EQ(stages.front(), "growing the packing");
  EXPECT_EQ(seen.front(), 0.0);
  // Each stage's fraction rises within [0, 1].
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_GE(seen[i], 0.0);
    EXPECT_LE(seen[i], 1.0);
    if (i > 0 && stages[i] == stages[i - 1]) {
      EXPECT_GE(seen[i], seen[i - 1]) << i;
    }
  }
  // Without a monitor nothing is reported (the scope ended).
  const std::size_t before = seen.size();
  const ShearCell again(cell());
  EXPECT_EQ(seen.size(), before);
}

TEST(SetupMonitor, AStopRequestAbandonsTheSetUpAndWritesNoResults) {
  std::atomic<bool> stop{false};
  int passes = 0;
  const ScopedSetupMonitor monitor({.stop = &stop, .progress = [&](std::string_view, double) {
                                      if (++passes == 3) stop.store(true);  // Ctrl-C mid-growth
                                    }});
  EXPECT_THROW(ShearCell{cell()}, SetupInterrupted);
  EXPECT_EQ(passes, 3);
  // Through the run loop (the CLI's path): the stop flag is the run's own.
  const auto out = std::filesystem::temp_directory_path() / "dilatant_setup_stop";
  std::filesystem::remove_all(out);
  CellRunOptions options{RunOptions{out, true}, false, &stop};
  options.stop_setup = &stop;
  EXPECT_THROW(run_shear_cell(cell(), options), SetupInterrupted);
  EXPECT_FALSE(std::filesystem::exists(out / "config.toml"));
  EXPECT_FALSE(std::filesystem::exists(out / "checkpoint.bin"));
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace dilatant::drivers::setup_monitor_test
