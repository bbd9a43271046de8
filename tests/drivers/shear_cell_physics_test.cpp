// Physics of the shear cell in steady flow, on a small cell (8 x 5 x 9 R, ~30
// mobile spheres) in the viscous regime (lambda = 1), where the flow reaches its
// steady state within 2 strain units. Tolerances are the runs' own block-averaged
// error bars (flow_series.hpp), at 3 sigma. The paper's literal model (no fluid
// forces; with them: shear_cell_fluid_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "drivers/cell_run_helpers.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "drivers/shear_cell_run.hpp"
#include "drivers/shear_cell_state.hpp"
#include "io/config.hpp"

namespace dilatant::shear_cell_physics_test {
namespace {

const std::vector<std::string> kCell = {
    "cell.size=[8.0, 5.0, 9.0]", "fluid.lambda=1.0",         "run.strain=6.0",
    "run.transient_strain=2.0",  "run.output_interval=0.02", "run.snapshot_interval=0.0",
    "fluid.lubrication=none",    "fluid.drag=none"};

class SteadyShear : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::cell_run_dir("steady");
    summary_ = test::run_cell_in(dir_, kCell);
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

// The particle stress tensor (measure/particle_stress.hpp): in steady flow its
// sigma_zx is the applied shear stress, and -sigma_zz the walls' normal
// stress (the identity behind both is checked to round-off in
// shear_cell_stress_test.cpp; here the averages, within 3 of the run's error
// bars, bounded so that a noisy run cannot pass more easily).
TEST_F(SteadyShear, ParticleStressCarriesTheAppliedStress) {
  const double tau = summary_["shear_stress"], measured = summary_["shear_stress_measured"];
  const double err = summary_["shear_stress_measured_err"];
  ASSERT_GT(err, 0.0);
  // 4 strain units of ~30 spheres: about 11% (the bottom wall's force: 14%).
  ASSERT_LT(err, 0.2 * tau);
  EXPECT_NEAR(measured, tau, 3.0 * err);
  const double p_wall = summary_["normal_stress"], p_wall_err = summary_["normal_stress_err"];
  const double zz = summary_["stress_tensor"][2][2];
  ASSERT_LT(p_wall_err, 0.2 * p_wall);
  EXPECT_NEAR(-zz, p_wall, 3.0 * p_wall_err);
  // A compressed, frictional packing: positive pressure, 0 < mu_eff < 1.
  EXPECT_GT(summary_["pressure"].get<double>(), 0.0);
  EXPECT_GT(summary_["mu_eff"].get<double>(), 0.0);
  EXPECT_LT(summary_["mu_eff"].get<double>(), 1.0);
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
  // Where it was is named, and held to the same tolerance.
  EXPECT_FALSE(summary_["overlap_exceeded"].get<bool>());
  EXPECT_DOUBLE_EQ(summary_["overlap_tolerance"].get<double>(), 0.01 * 0.8);
  EXPECT_GE(summary_["max_overlap_step"].get<long>(), 0);
  EXPECT_LE(summary_["max_overlap_step"].get<long>(), summary_["steps"].get<long>());
  ASSERT_EQ(summary_["max_overlap_bodies"].size(), 2u);
  EXPECT_GE(summary_["max_overlap_bodies"][0].get<long>(), 0);
}

// Energy: the drive's power goes into perfectly inelastic impacts, friction and
// kinetic energy. The split is exact step by step (solver/contact_work.hpp), so
// the steady averages must balance to round-off, and every loss is a loss.
TEST_F(SteadyShear, EnergyBudgetCloses) {
  const double injected = summary_["power_injected"];
  const double impacts = summary_["power_impacts"], bl = summary_["power_friction_bl"],
               hd = summary_["power_friction_hd"], kinetic = summary_["power_kinetic"];
  EXPECT_GT(injected, 0.0);
  EXPECT_GE(impacts, 0.0);
  EXPECT_GE(bl, 0.0);
  EXPECT_GE(hd, 0.0);
  EXPECT_NEAR(injected, impacts + bl + hd + kinetic, 1e-9 * injected);
  // Steady state: no net change of kinetic energy within its error bar.
  EXPECT_NEAR(kinetic, 0.0, 3.0 * summary_["power_kinetic_err"].get<double>());
  // Hydrodynamic contacts slide persistently: their friction loss is the
  // force times the sliding speed (to the step's discretisation).
  EXPECT_NEAR(summary_["power_sliding_hd"].get<double>(), hd,
              3.0 * summary_["power_friction_hd_err"].get<double>());
  // The drive's power is tau A <v_wall> (the discrete work differs by O(dt)).
  EXPECT_NEAR(injected,
              summary_["applied_force_x"].get<double>() * summary_["wall_velocity"].get<double>(),
              3.0 * summary_["power_injected_err"].get<double>());
}

// The bottom wall is fixed: its spheres end exactly where they were built.
TEST_F(SteadyShear, FixedWallDoesNotDrift) {
  ShearCellGeometry g;
  RoughWalls walls;
  const World built = build_shear_cell(default_cell_config(kCell), g, walls);
  const ShearCellState end = load_checkpoint(dir_ / "checkpoint.bin");
  int bottom = 0;
  for (std::size_t i = 0; i < built.bodies.size(); ++i) {
    if (built.bodies.owner[i] != kBottomWall) continue;
    EXPECT_EQ(end.world.bodies.position[i], built.bodies.position[i]);
    ++bottom;
  }
  EXPECT_GE(bottom, 6);  // an RSA monolayer covers ~55% of the 8 x 5 area with r ~ 0.9 discs
}

}  // namespace
}  // namespace dilatant::shear_cell_physics_test
