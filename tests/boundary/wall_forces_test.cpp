// Forces of the contacts on the shear cell's walls (boundary/wall_forces.hpp):
// impulse over dt, with Newton's third law fixing the sign.
#include "boundary/wall_forces.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dilatant::wall_forces_test {
namespace {

Contact contact(int i, int other, const Vec3& normal, double p_n, const Vec3& p_t) {
  Contact c;
  c.i = i;
  c.other = other;
  c.normal = normal;
  c.p_n = p_n;
  c.p_t = p_t;
  return c;
}

// Body 0: bottom-wall sphere, 1: particle, 2: top-wall sphere. The particle
// is squeezed between the walls: the impulse P on i acts as -P on the partner.
TEST(WallForces, SqueezedParticlePushesBothWallsApart) {
  Bodies bodies;
  for (int i = 0; i < 3; ++i) bodies.add_sphere(i, Vec3(0.0, 0.0, i), 0.5, 1.0, i != 1);
  bodies.set_driven(0, kBottomWall);
  bodies.set_driven(2, kTopWall);
  const double dt = 0.01;
  const std::vector<Contact> contacts = {
      // particle (i) on the bottom sphere: normal from the bottom sphere up to it.
      contact(1, 0, Vec3::UnitZ(), 0.02, Vec3(0.005, 0.0, 0.0)),
      // top sphere (i) on the particle: normal from the particle up to the wall.
      contact(2, 1, Vec3::UnitZ(), 0.03, Vec3(-0.001, 0.0, 0.0)),
      // an open contact carries nothing.
      contact(1, 2, Vec3::UnitZ(), 0.0, Vec3(1.0, 0.0, 0.0))};
  const WallForces f = wall_forces(bodies, contacts, dt);
  EXPECT_NEAR((f.bottom - Vec3(-0.5, 0.0, -2.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((f.top - Vec3(-0.1, 0.0, 3.0)).norm(), 0.0, 1e-14);
}

// Safety planes: plane 0 (z = 0) belongs to the bottom wall, plane 1 to the top.
TEST(WallForces, SafetyPlanesCountForTheirWall) {
  Bodies bodies;
  bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0), 0.5, 1.0, false);
  const std::vector<Contact> contacts = {contact(0, -1, Vec3::UnitZ(), 1.0, Vec3::Zero()),
                                         contact(0, -2, -Vec3::UnitZ(), 2.0, Vec3::Zero())};
  const WallForces f = wall_forces(bodies, contacts, 0.5);
  EXPECT_EQ(f.bottom, Vec3(0.0, 0.0, -2.0));
  EXPECT_EQ(f.top, Vec3(0.0, 0.0, 4.0));
}

}  // namespace
}  // namespace dilatant::wall_forces_test
