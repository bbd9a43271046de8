// The stress that sets the unit of the solver's residual in the shear cell
// (drivers/cell_time_step.hpp reference_stress(); docs/model.md "Convergence
// criterion"): the applied one under stress control, whatever the flow does;
// under rate control the last row's measured |sigma_zx|, never below the
// Bagnold stress rho_p (2 R gamma_dot)^2 nor the viscous eta_f gamma_dot.
// And the automatic step (choose_time_step()): in the lab frame it shrinks as
// a Lees–Edwards box grows (the top moves at gamma_dot Lz / 2); relative to the
// drive's mean flow it does not.
#include "drivers/cell_time_step.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "boundary/image_drive.hpp"

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

// A rate-controlled Lees–Edwards box of height lz (gamma_dot 0.1) with three
// spheres of radius 1 moving exactly with the homogeneous shear about lz / 2,
// the middle one also `excess` faster along y.
struct AffineBox {
  World world;
  ImageDrive drive;
  AffineBox(double lz, double excess)
      : drive(ImageDrive::control_for({.kind = DriveKind::Images,
                                       .rate_controlled = true,
                                       .shear_rate = 0.1,
                                       .size = Vec3(10.0, 10.0, lz)},
                                      0.0)) {
    world.box.length = Vec3(10.0, 10.0, lz);
    world.box.periodic = {true, true, true};
    world.box.lees_edwards = true;
    world.box.shear_velocity = 0.1 * lz;
    for (const double z : {0.1 * lz, 0.5 * lz, 0.9 * lz}) {
      const Vec3 v(0.1 * (z - 0.5 * lz), z == 0.5 * lz ? excess : 0.0, 0.0);
      world.bodies.add_sphere(0, Vec3(5.0, 5.0, z), 1.0, 1.0, false, v);
    }
  }
  TimeStepChoice step(StepFrame frame) const {
    SolverConfig solver;
    solver.step_frame = frame;
    return choose_time_step(world, drive, solver);
  }
};

TEST(CellTimeStep, InTheLabFrameTheStepShrinksWithTheBoxHeight) {
  // c r_min / V with V = gamma_dot lz: the images set it (the drive's bound).
  for (const double lz : {10.0, 40.0}) {
    const TimeStepChoice lab = AffineBox(lz, 0.0).step(StepFrame::Lab);
    EXPECT_DOUBLE_EQ(lab.dt, 0.02 / (0.1 * lz)) << "lz " << lz;
    EXPECT_FALSE(lab.mean_flow.has_value());
  }
}

TEST(CellTimeStep, RelativeToTheMeanFlowTheStepDoesNotDependOnTheHeight) {
  // Bodies on the affine profile: only the shear between neighbours, gamma_dot
  // R_max, bounds the step, c r_min / (gamma_dot R_max) = 0.2, as the drive's
  // own bound over a span R_max does.
  for (const double lz : {10.0, 40.0}) {
    const TimeStepChoice flow = AffineBox(lz, 0.0).step(StepFrame::MeanFlow);
    EXPECT_DOUBLE_EQ(flow.dt, 0.02 / (0.1 * 1.0)) << "lz " << lz;
    ASSERT_TRUE(flow.mean_flow.has_value());
    EXPECT_DOUBLE_EQ(flow.mean_flow->shear_rate, 0.1);
    EXPECT_DOUBLE_EQ(flow.mean_flow->z0, 0.5 * lz);
  }
  // A body 0.3 faster than the flow at its height: c r_min / (0.3 + gamma_dot
  // R_max), whatever its height.
  EXPECT_DOUBLE_EQ(AffineBox(40.0, 0.3).step(StepFrame::MeanFlow).dt, 0.02 / (0.3 + 0.1));
}

}  // namespace
}  // namespace dilatant::drivers::cell_time_step_test
