// The shear cell as an object (drivers/shear_cell.hpp): stepped by hand it is
// the same simulation as the CLI's run loop, and its state can be read while
// it runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_run.hpp"

namespace dilatant::shear_cell_object_test {
namespace {

Config tiny_cell() {
  return default_cell_config({"cell.size=[6.0, 5.0, 7.0]", "run.strain=0.03",
                              "run.transient_strain=0.01", "run.output_interval=0.005",
                              "run.snapshot_interval=0", "solver.max_iterations=200"});
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("dilatant_object_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

std::string read(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShearCellObject, SteppedByHandEqualsTheRunLoop) {
  const Config config = tiny_cell();
  const auto by_hand = fresh_dir("hand"), by_loop = fresh_dir("loop");

  ShearCell cell(config);
  EXPECT_EQ(cell.state().steps, 0);
  EXPECT_EQ(cell.fraction_done(), 0.0);
  double strain = 0.0;
  while (!cell.done()) {
    const StepReport& r = cell.step();
    EXPECT_TRUE(r.solve.converged || r.solve.iterations == 200);
    // The strain grows by the wall's displacement over the height, step by step.
    EXPECT_GT(cell.state().strain, strain);
    strain = cell.state().strain;
  }
  EXPECT_GE(cell.state().strain, config.run.strain);
  EXPECT_EQ(cell.fraction_done(), 1.0);
  cell.finish();
  cell.write_results(by_hand, RunCost{});

  run_shear_cell(config, CellRunOptions{RunOptions{by_loop, true}});
  for (const char* f :
       {"timeseries.csv", "contacts.csv", "velocity_profile.csv", "sommerfeld_hist.csv"}) {
    EXPECT_EQ(read(by_hand / f), read(by_loop / f)) << f;
  }
  const auto a = nlohmann::json::parse(read(by_hand / "summary.json"));
  const auto b = nlohmann::json::parse(read(by_loop / "summary.json"));
  for (const char* key : {"steps", "eta", "gamma_dot", "frac_bl", "normal_stress", "phi_bulk"}) {
    EXPECT_EQ(a[key], b[key]) << key;
  }
  std::filesystem::remove_all(by_hand);
  std::filesystem::remove_all(by_loop);
}

// The units are computed once, from lambda: eta_f = 1/lambda in code units,
// and the contacts of the state are those of the last step.
TEST(ShearCellObject, ExposesUnitsAndContacts) {
  ShearCell cell(default_cell_config({"cell.size=[6.0, 5.0, 7.0]", "fluid.lambda=25",
                                      "run.strain=0.01", "run.transient_strain=0"}));
  EXPECT_DOUBLE_EQ(cell.units().eta_f, 1.0 / 25.0);
  cell.step();
  EXPECT_FALSE(cell.contacts().empty());
  for (const Contact& c : cell.contacts()) EXPECT_GE(c.p_n, 0.0);
  EXPECT_EQ(cell.state().steps, 1);
  EXPECT_NE(cell.progress_line(1.0).find("strain"), std::string::npos);
}

}  // namespace
}  // namespace dilatant::shear_cell_object_test
