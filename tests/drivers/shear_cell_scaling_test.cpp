// Bagnold scaling of dry frictional grains: with the `coulomb` law no fluid
// enters, so the only time scale of the stress-controlled cell is
// R sqrt(rho_p / tau) and doubling tau must multiply the shear rate by sqrt(2)
// (stress ~ rho R^2 gdot^2). Small cell; tolerance 3 combined standard errors.
// The same runs check that s_lim does not decide the validity of a coulomb run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "drivers/cell_run_helpers.hpp"

namespace dilatant::shear_cell_scaling_test {
namespace {

nlohmann::json run_coulomb_cell(double tau) {
  const std::vector<std::string> overrides = {
      "cell.size=[8.0, 5.0, 9.0]", "friction.law=coulomb", "friction.mu0=0.1",
      // eta_f only sets the units here; at
      // lambda 1 many contacts pass s_lim.
      "fluid.lambda=1.0", "cell.shear_stress=" + std::to_string(tau), "run.strain=5.0",
      "run.transient_strain=2.0", "run.output_interval=0.02", "run.snapshot_interval=0.0",
      "fluid.lubrication=none", "fluid.drag=none"};
  const auto summary = test::run_cell_summary("bagnold_" + std::to_string(tau), overrides);
  return summary;
}

TEST(CellScaling, DoublingTheStressMultipliesTheRateBySqrt2) {
  const auto one = run_coulomb_cell(1.0);
  const auto two = run_coulomb_cell(2.0);
  ASSERT_FALSE(one["jammed"].get<bool>());
  const double v1 = one["wall_velocity"], v2 = two["wall_velocity"];
  const double e1 = one["wall_velocity_err"], e2 = two["wall_velocity_err"];
  ASSERT_GT(e1, 0.0);
  ASSERT_GT(e2, 0.0);
  const double ratio = v2 / v1;
  const double ratio_err = ratio * std::hypot(e1 / v1, e2 / v2);
  EXPECT_NEAR(ratio, std::sqrt(2.0), 3.0 * ratio_err);

  // The control has no lubrication to break down: its Sommerfeld numbers run
  // past s_lim (they mean nothing here), and validity must not depend on them.
  for (const auto* summary : {&one, &two}) {
    const auto& r = *summary;
    EXPECT_GT(r["frac_over_slim"].get<double>(), 0.05);
    EXPECT_EQ(r["valid"].get<bool>(), !r["jammed"].get<bool>() &&
                                          r["profile_consistent"].get<bool>() &&
                                          r["steady"] != false);
  }
}

}  // namespace
}  // namespace dilatant::shear_cell_scaling_test
