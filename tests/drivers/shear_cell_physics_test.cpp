// Physics of the shear cell in steady flow, on a small cell (8 x 5 x 9 R, ~30
// mobile spheres) in the viscous regime (lambda = 1), where the flow reaches its
// steady state within 2 strain units. Tolerances are the runs' own block-averaged
// error bars (flow_series.hpp), at 3 sigma.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "drivers/shear_cell_builder.hpp"
#include "drivers/shear_cell_run.hpp"
#include "drivers/shear_cell_state.hpp"
#include "io/config.hpp"

namespace dilatant {
namespace {

const std::vector<std::string> kCell = {
    "cell.size=[8.0, 5.0, 9.0]", "fluid.lambda=1.0",         "run.strain=6.0",
    "run.transient_strain=2.0",  "run.output_interval=0.02", "run.snapshot_interval=0.0",
    "solver.tolerance=1e-4"};

class SteadyShear : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ =
        std::filesystem::temp_directory_path() / ("dilatant_steady_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    run_shear_cell(default_cell_config(kCell),
                   CellRunOptions{RunOptions{dir_, true}, false, nullptr});
    std::ifstream in(dir_ / "summary.json");
    summary_ = nlohmann::json::parse(in);
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::filesystem::path dir_;
  static nlohmann::json summary_;
};
std::filesystem::path SteadyShear::dir_;
nlohmann::json SteadyShear::summary_;

TEST_F(SteadyShear, FlowsAndConverges) {
  EXPECT_FALSE(summary_["jammed"].get<bool>());
  EXPECT_GT(summary_["gamma_dot"].get<double>(), 0.0);
  EXPECT_GT(summary_["gamma_dot_err"].get<double>(), 0.0);  // enough steady blocks
  EXPECT_LT(summary_["frac_steps_unconverged"].get<double>(), 0.05);
}

// Momentum balance: in steady flow the fixed wall takes, on average, the whole
// force that drives the moving one.
TEST_F(SteadyShear, BottomWallCarriesTheAppliedForce) {
  const double applied = summary_["applied_force_x"];
  const double measured = summary_["bottom_wall_force_x"];
  const double err = summary_["bottom_wall_force_x_err"];
  ASSERT_GT(err, 0.0);
  EXPECT_NEAR(measured, applied, 3.0 * err);
}

// Constant volume: the particles push both walls apart equally.
TEST_F(SteadyShear, NormalForceEqualOnBothWalls) {
  const double top = summary_["top_wall_force_z"], bottom = summary_["bottom_wall_force_z"];
  const double err = std::hypot(summary_["top_wall_force_z_err"].get<double>(),
                                summary_["bottom_wall_force_z_err"].get<double>());
  EXPECT_GT(top, 0.0);
  EXPECT_NEAR(top, -bottom, 3.0 * err);
}

// Perfect volume exclusion: overlaps come only from linearising the gap over one
// step, of order (displacement per step)^2 / r = (0.02 r)^2 / r = 4e-4 r, and
// from unconverged solves; 1% of the smallest radius bounds both.
TEST_F(SteadyShear, NoOverlapAboveTolerance) {
  EXPECT_LT(summary_["max_overlap"].get<double>(), 0.01 * 0.8);
}

// The bottom wall is fixed: its spheres end exactly where they were built.
TEST_F(SteadyShear, FixedWallDoesNotDrift) {
  ShearCellGeometry g;
  const World built = build_shear_cell(default_cell_config(kCell), g);
  const ShearCellState end = load_checkpoint(dir_ / "checkpoint.bin");
  int bottom = 0;
  for (std::size_t i = 0; i < built.bodies.size(); ++i) {
    if (built.group[i] != BodyGroup::BottomWall) continue;
    EXPECT_EQ(end.world.bodies.position[i], built.bodies.position[i]);
    ++bottom;
  }
  EXPECT_GE(bottom, 6);  // an RSA monolayer covers ~55% of the 8 x 5 area with r ~ 0.9 discs
}

}  // namespace
}  // namespace dilatant
