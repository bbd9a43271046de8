// The stress that sets the unit of the solver's residual in the shear cell
// (drivers/cell_time_step.hpp reference_stress(); docs/model.md "Convergence
// criterion"): the applied one under stress control, whatever the flow does;
// under rate control the last row's measured |sigma_zx|, never below the
// Bagnold stress rho_p (2 R gamma_dot)^2 nor the viscous eta_f gamma_dot.
#include "drivers/cell_time_step.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dilatant::drivers::cell_time_step_test {
namespace {

FlowRow row_with_shear_stress(double sigma_zx) {
  FlowRow r;
  r.stress[tensor_index(kZ, kX)] = sigma_zx;
  return r;
}

TEST(ReferenceStress, StressControlTakesTheAppliedStress) {
  CellConfig cell;
  cell.shear_stress = 2.5;
  EXPECT_EQ(reference_stress(cell, 1.0, 0.1, {}), 2.5);
  // A locked-in stress far above the applied one does not move it.
  EXPECT_EQ(reference_stress(cell, 1.0, 0.1, {row_with_shear_stress(400.0)}), 2.5);
}

TEST(ReferenceStress, RateControlTakesTheMeasuredStressAboveTheBagnoldAndViscousOnes) {
  CellConfig cell;
  cell.control = ShearControl::Rate;
  cell.shear_rate = 0.01;
  cell.radius_max = 1.5;
  const double density = 2.0, eta_f = 0.5;
  const double bagnold = density * (2.0 * 1.5 * 0.01) * (2.0 * 1.5 * 0.01);  // 1.8e-3
  const double viscous = eta_f * 0.01;                                       // 5e-3
  // No row yet: the larger floor, here the viscous one; then the dry one alone.
  EXPECT_DOUBLE_EQ(reference_stress(cell, density, eta_f, {}), viscous);
  EXPECT_DOUBLE_EQ(reference_stress(cell, density, 0.0, {}), bagnold);
  // The last row's measured stress, of either sign, once above both.
  const std::vector<FlowRow> rows = {row_with_shear_stress(1.0), row_with_shear_stress(-0.2)};
  EXPECT_DOUBLE_EQ(reference_stress(cell, density, eta_f, rows), 0.2);
  EXPECT_DOUBLE_EQ(reference_stress(cell, density, eta_f, {row_with_shear_stress(1e-4)}), viscous);
}

}  // namespace
}  // namespace dilatant::drivers::cell_time_step_test
