// The particle stress tensor in the wall cell (measure/particle_stress.hpp)
// against the momentum balance it comes from. Summed over the steps of a
// window, the contact virial plus the kinetic term equals, to round-off, the
// drive's moment and the change of the bodies' momentum moments:
//
//   sum_steps [ sum_c r_z P_x + dt sum_n m v_z v_x ]
//       = [ sum_n z m v_x + Lz M V ]_start^end - Lz F T          (x force)
//   sum_steps [ sum_c r_z P_z + dt sum_n m v_z v_z ]
//       = [ sum_n z m v_z ]_start^end + Lz sum_steps P_top,z      (z force)
//
// (walls' centres at z = 0 and Lz, the top wall rigid with mass M, speed V,
// drive F; no gravity and no drag in the literal model). So the measured
// shear stress is the applied one plus boundary terms that vanish as 1/T,
// and sigma_zz is minus the walls' normal stress.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/wall_drive.hpp"
#include "drivers/shear_cell.hpp"
#include "measure/particle_stress.hpp"

namespace dilatant::shear_cell_stress_test {
namespace {

struct Moments {
  double x = 0.0, z = 0.0;  // sum_n z m v_x and sum_n z m v_z over mobile bodies
};

Moments momentum_moments(const Bodies& b) {
  Moments m;
  for (std::size_t n = 0; n < b.size(); ++n) {
    if (b.is_fixed(n)) continue;
    m.x += b.position[n][kZ] * b.mass(n) * b.velocity[n][kX];
    m.z += b.position[n][kZ] * b.mass(n) * b.velocity[n][kZ];
  }
  return m;
}

TEST(ParticleStress, TheWallCellsVirialBalancesTheDriveStepByStep) {
  const Config config = default_cell_config(
      {"cell.size=[6.0, 5.0, 7.0]", "run.transient_strain=0.5", "run.strain=1.0",
       "run.snapshot_interval=0", "solver.max_iterations=200", "fluid.lambda=10.0"});
  ShearCell cell(config);
  // Past the start, where contacts form.
  for (int k = 0; k < 200; ++k) cell.step();

  const double lz = config.cell()->size[2];
  const SlidingWall& wall = dynamic_cast<const WallDrive&>(*cell.state().drive).walls().top();
  const Moments start = momentum_moments(cell.state().world.bodies);
  const double wall_start = wall.mass * wall.velocity;
  double virial_zx = 0.0, virial_zz = 0.0, top_impulse_z = 0.0, time = 0.0, scale = 0.0;
  for (int k = 0; k < 400; ++k) {
    cell.step();
    const double dt = cell.state().dt;
    const Tensor3 v = contact_impulse_moment(cell.contacts());
    const Tensor3 kinetic = velocity_fluctuation_moment(cell.state().world.bodies, {});
    virial_zx += v[tensor_index(kZ, kX)] + dt * kinetic[tensor_index(kZ, kX)];
    virial_zz += v[tensor_index(kZ, kZ)] + dt * kinetic[tensor_index(kZ, kZ)];
    top_impulse_z +=
        cell.state().drive->wall_forces(cell.state().world, cell.contacts(), dt).top[kZ] * dt;
    scale += std::abs(v[tensor_index(kZ, kZ)]);
    time += dt;
  }
  const Moments end = momentum_moments(cell.state().world.bodies);
  const double expected_zx = (end.x - start.x) + lz * (wall.mass * wall.velocity - wall_start) -
                             lz * wall.drive_force * time;
  const double expected_zz = (end.z - start.z) + lz * top_impulse_z;
  // Round-off of sums of ~1e5 terms of size `scale / steps`.
  EXPECT_NEAR(virial_zx, expected_zx, 1e-9 * scale);
  EXPECT_NEAR(virial_zz, expected_zz, 1e-9 * scale);
  // Not a trivial identity: both sides are of the drive's size.
  EXPECT_GT(std::abs(expected_zx), 0.1 * lz * wall.drive_force * time);
}

}  // namespace
}  // namespace dilatant::shear_cell_stress_test
