// The bodies' arrays (world/bodies.hpp): masses of solid spheres, kinetic
// energy and momentum, and the reordering that keeps each body's data together.
#include "world/bodies.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

namespace dilatant::bodies_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(Bodies, SolidSpheresHaveTheirMassAndMomentOfInertia) {
  Bodies b;
  b.add_sphere(7, Vec3::Zero(), 0.5, 2.0, false);
  const double m = 4.0 / 3.0 * std::numbers::pi * 2.0 * 0.125;
  EXPECT_NEAR(b.mass(0), m, 4 * kEps * m);
  EXPECT_NEAR(1.0 / b.inv_inertia[0], 0.4 * m * 0.25, 4 * kEps * m);  // I = 2/5 m r^2
  EXPECT_EQ(b.id[0], 7);
  // A fixed sphere has infinite mass and no velocity, whatever was asked.
  b.add_sphere(8, Vec3::Zero(), 0.5, 2.0, true, Vec3(1.0, 0.0, 0.0));
  EXPECT_TRUE(b.is_fixed(1));
  EXPECT_EQ(b.mass(1), 0.0);
  EXPECT_EQ(b.velocity[1], Vec3::Zero());
}

// KE = sum m v^2/2 + I w^2/2 and p = sum m v, over the mobile bodies only.
TEST(Bodies, KineticEnergyAndMomentumCountMobileBodies) {
  Bodies b;
  b.add_sphere(0, Vec3::Zero(), 1.0, 1.0, false, Vec3(1.0, 2.0, 0.0), Vec3(0.0, 0.0, 3.0));
  b.add_sphere(1, Vec3(5.0, 0.0, 0.0), 1.0, 1.0, false, Vec3(-1.0, 0.0, 0.0));
  b.add_sphere(2, Vec3(9.0, 0.0, 0.0), 1.0, 1.0, true);
  b.velocity[2] = Vec3(4.0, 0.0, 0.0);  // a driven wall sphere: infinite mass, counts nothing
  const double m = b.mass(0), inertia = 0.4 * m;
  EXPECT_NEAR(b.kinetic_energy(), 0.5 * m * 5.0 + 0.5 * inertia * 9.0 + 0.5 * m * 1.0, 1e-13);
  EXPECT_NEAR((b.momentum() - Vec3(0.0, 2.0 * m, 0.0)).norm(), 0.0, 1e-14);
}

TEST(Bodies, ReorderMovesEveryArrayTogether) {
  Bodies b;
  for (int k = 0; k < 4; ++k) {
    b.add_sphere(10 + k, Vec3(k, 0.0, 0.0), 0.5 + 0.1 * k, 1.0, k == 0, Vec3(0.0, k, 0.0));
  }
  b.reorder(1, {3, 1, 2});
  EXPECT_EQ(b.id[0], 10);  // before `first`: untouched
  EXPECT_EQ(b.id[1], 13);
  EXPECT_EQ(b.position[1], Vec3(3.0, 0.0, 0.0));
  EXPECT_EQ(b.velocity[1], Vec3(0.0, 3.0, 0.0));
  EXPECT_DOUBLE_EQ(b.radius[1], 0.8);
  EXPECT_EQ(b.id[3], 12);
  EXPECT_DOUBLE_EQ(b.mass(1), 4.0 / 3.0 * std::numbers::pi * 0.8 * 0.8 * 0.8);
}

}  // namespace
}  // namespace dilatant::bodies_test
