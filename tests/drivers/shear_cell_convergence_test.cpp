// Numerical convergence of a shear-cell flow point (small cell, viscous regime):
// tightening the Gauss–Seidel tolerance tenfold must not move eta or P_BL beyond
// the runs' combined error bars (3 sigma).
//
// Not here, because it does not hold yet: halving the time step. At lambda = 1
// P_BL falls with dt (3 seeds, solver.max_displacement 0.02 / 0.01 / 0.005:
// 0.032 / 0.021 / 0.014 on average) -- in an implicit step a sliding contact
// sticks when mu0 N dt can stop it, so the stick fraction is first order in dt.
// See docs/shear-cell.md, "Open problems".
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

}  // namespace
}  // namespace dilatant
