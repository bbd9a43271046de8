// Numerical convergence of a shear-cell flow point (small cell, viscous regime):
// tightening the Gauss–Seidel tolerance tenfold, or halving the time step, must
// not move eta or P_BL beyond the runs' combined error bars (3 sigma).
//
// The time-step check guards the continuity of the HD branch
// (friction/stribeck_law.hpp): without it a sliding contact stuck whenever
// mu0 N dt could stop it, and at this lambda P_BL fell from 0.032 to 0.021 and
// eta from 5.8 to 4.8 when dt was halved (3 seeds), far beyond error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "drivers/cell_run_helpers.hpp"

namespace dilatant {
namespace {

// Runs are cached by name within the process: the reference point is shared.
nlohmann::json run_small_cell(const std::string& name, const std::vector<std::string>& extra) {
  static std::map<std::string, nlohmann::json> cache;
  if (const auto it = cache.find(name); it != cache.end()) return it->second;
  std::vector<std::string> overrides = {
      "cell.size=[8.0, 5.0, 9.0]", "fluid.lambda=1.0",         "run.strain=6.0",
      "run.transient_strain=2.0",  "run.output_interval=0.02", "run.snapshot_interval=0.0",
      "solver.tolerance=1e-4"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  const auto summary = testing::run_cell_summary("conv_" + name, overrides);
  cache[name] = summary;
  return summary;
}

// |a - b| within 3 combined standard errors; the error of frac_bl is taken from
// its block average like eta's (both come from the same steady blocks).
void expect_same_point(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_GT(a["eta_err"].get<double>(), 0.0);
  ASSERT_GT(b["eta_err"].get<double>(), 0.0);
  EXPECT_NEAR(a["eta"].get<double>(), b["eta"].get<double>(),
              3.0 * std::hypot(a["eta_err"].get<double>(), b["eta_err"].get<double>()));
  EXPECT_NEAR(a["frac_bl"].get<double>(), b["frac_bl"].get<double>(),
              3.0 * std::hypot(a["frac_bl_err"].get<double>(), b["frac_bl_err"].get<double>()));
}

TEST(CellConvergence, TenfoldTighterToleranceKeepsEtaAndBoundaryFraction) {
  const auto loose = run_small_cell("reference", {});
  const auto tight = run_small_cell("tol5", {"solver.tolerance=1e-5"});
  expect_same_point(loose, tight);
}

// The automatic step is dt = c r_min / v_max (c = solver.max_displacement):
// halving c halves dt.
TEST(CellConvergence, HalvedTimeStepKeepsEtaAndBoundaryFraction) {
  const auto coarse = run_small_cell("reference", {});
  const auto fine = run_small_cell("dt_half", {"solver.max_displacement=0.01"});
  ASSERT_GT(coarse["steps"].get<double>(), 0.0);
  // Same strain in twice the steps, give or take the flow's own fluctuations.
  EXPECT_GT(fine["steps"].get<double>(), 1.5 * coarse["steps"].get<double>());
  expect_same_point(coarse, fine);
}

}  // namespace
}  // namespace dilatant
