// The viscous side of the flow curve (paper p. 1 and Fig. 2: a Newtonian
// viscosity at low shear rate, independent of mu0). At lambda = 0.3 almost all
// sliding contacts are hydrodynamically lubricated, so the boundary friction
// mu0 should not matter: eta at mu0 = 0.1 and 0.4 must agree within 3 combined
// standard errors of kSeeds-seed means (measured with 3 seeds: 3.41 +- 0.26 and
// 2.82 +- 0.54 eta_f).
//
// Size (cell_run_helpers.hpp): at lambda 0.3 the seeds scatter more than at
// lambda 1: s = 0.31 for gamma_dot averaged over 1 or 2 strain, 0.26 over 4,
// 0.24 over 8 (scripts/seed_scatter.py, 12 seeds of 10 strain, mu0 0.1). So 4
// seeds of 2 + 4 strain catch a mu0 dependence of 55% of eta at three combined
// standard errors: a guard against mu0 acting through unlubricated contacts,
// not a measurement of a small one; a 5% dependence would need 490 seeds a
// setting (s = 0.26; docs/testing.md).
//
// Not tested, because it does not hold in the model as specified: eta
// independent of lambda. eta keeps falling with lambda down to 0.01
// (docs/shear-cell.md, "Open problems", item 3).
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/cell_run_helpers.hpp"

namespace dilatant::shear_cell_viscous_test {
namespace {

std::vector<nlohmann::json> viscous_cells(const std::string& name, const std::string& mu0) {
  return test::run_cell_seeds(
      name, {"cell.size=[8.0, 5.0, 9.0]", "fluid.lambda=0.3", "friction.mu0=" + mu0,
             "run.output_interval=0.02", "run.snapshot_interval=0.0", "fluid.lubrication=none",
             "fluid.drag=none"});
}

TEST(CellViscous, ViscosityDoesNotDependOnBoundaryFriction) {
  const auto low = test::seed_mean(viscous_cells("visc_mu01", "0.1"), "eta");
  const auto high = test::seed_mean(viscous_cells("visc_mu04", "0.4"), "eta");
  ASSERT_GT(low.error, 0.0);
  ASSERT_GT(high.error, 0.0);
  EXPECT_NEAR(low.mean, high.mean, 3.0 * std::hypot(low.error, high.error));
}

}  // namespace
}  // namespace dilatant::shear_cell_viscous_test
