// The particle stress tensor's pieces on hand-made states
// (measure/particle_stress.hpp); its balance with the drive in a running cell
// is tests/drivers/shear_cell_stress_test.cpp.
#include "measure/particle_stress.hpp"

#include <gtest/gtest.h>

namespace dilatant::particle_stress_test {
namespace {

// Two spheres (radii 1 and 0.5) pressed together along z with impulse P: the
// branch is 1.5 + gap along z, so only the zz entry is non-zero, r_z P_z.
TEST(ParticleStress, APairPressedAlongZGivesOnlyTheZzMoment) {
  Contact c;
  c.i = 0;
  c.other = 1;
  c.normal = Vec3(0.0, 0.0, 1.0);  // from the partner towards i: i is on top
  c.arm_i = 1.0;
  c.arm_j = 0.5;
  c.gap = -0.01;
  c.p_n = 2.0;
  const Tensor3 m = contact_impulse_moment({c});
  for (int k = 0; k < 9; ++k)
    EXPECT_DOUBLE_EQ(m[k], k == tensor_index(kZ, kZ) ? 1.49 * 2.0 : 0.0) << k;
  // Compression: sigma = -m / (V dt) has sigma_zz < 0 and a positive pressure.
  Tensor3 sigma{};
  for (int k = 0; k < 9; ++k) sigma[k] = -m[k];
  EXPECT_NEAR(invariants(sigma).pressure, 1.49 * 2.0 / 3.0, 1e-15);
}

// Friction: the tangential impulse of a contact whose branch is along z
// lands in the zx entry, which the wall cell calls its shear stress; the
// squeeze film adds along the normal like the contact; an open contact
// without impulse adds nothing.
TEST(ParticleStress, FrictionAlongXOfABranchAlongZIsTheZxEntry) {
  Contact c;
  c.normal = Vec3(0.0, 0.0, -1.0);
  c.arm_i = 1.0;
  c.arm_j = 1.0;
  c.p_n = 1.0;
  c.p_lub = 0.5;
  c.p_t = Vec3(0.3, 0.0, 0.0);
  Contact open;
  open.normal = Vec3(1.0, 0.0, 0.0);
  open.arm_i = 1.0;
  const Tensor3 m = contact_impulse_moment({c, open});
  EXPECT_DOUBLE_EQ(m[tensor_index(kZ, kX)], -2.0 * 0.3);
  EXPECT_DOUBLE_EQ(m[tensor_index(kZ, kZ)], 2.0 * 1.5);
  EXPECT_DOUBLE_EQ(m[tensor_index(kX, kZ)], 0.0);
  EXPECT_DOUBLE_EQ(m[tensor_index(kX, kX)], 0.0);
}

// A body moving with the mean shear flow has no velocity fluctuation; fixed
// bodies (the walls' spheres) count nothing.
TEST(ParticleStress, TheKineticPartCountsOnlyTheFluctuationOfMobileBodies) {
  Bodies b;
  const ShearFlow flow{.shear_rate = 2.0, .z0 = 1.0};
  b.add_sphere(0, Vec3(0.0, 0.0, 3.0), 1.0, 1.0, false, Vec3(4.0, 0.0, 0.0));  // on the flow
  b.add_sphere(1, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, false, Vec3(1.0, 0.0, 2.0));
  b.add_sphere(2, Vec3(0.0, 0.0, 5.0), 1.0, 1.0, true, Vec3(9.0, 9.0, 9.0));
  const Tensor3 m = velocity_fluctuation_moment(b, flow);
  const double mass = b.mass(1);
  EXPECT_DOUBLE_EQ(m[tensor_index(kX, kX)], mass * 1.0);
  EXPECT_DOUBLE_EQ(m[tensor_index(kX, kZ)], mass * 2.0);
  EXPECT_DOUBLE_EQ(m[tensor_index(kZ, kX)], mass * 2.0);
  EXPECT_DOUBLE_EQ(m[tensor_index(kZ, kZ)], mass * 4.0);
  EXPECT_DOUBLE_EQ(m[tensor_index(kY, kY)], 0.0);
}

TEST(ParticleStress, InvariantsFollowTheRheologistsConvention) {
  Tensor3 s{};
  s[tensor_index(kX, kX)] = -1.0;
  s[tensor_index(kY, kY)] = -2.0;
  s[tensor_index(kZ, kZ)] = -4.0;
  s[tensor_index(kZ, kX)] = 0.7;
  s[tensor_index(kX, kZ)] = 0.6;
  const StressInvariants v = invariants(s);
  EXPECT_DOUBLE_EQ(v.shear, 0.7);
  EXPECT_DOUBLE_EQ(v.pressure, 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(v.n1, 3.0);   // xx - zz
  EXPECT_DOUBLE_EQ(v.n2, -2.0);  // zz - yy
}

}  // namespace
}  // namespace dilatant::particle_stress_test
