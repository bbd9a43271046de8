#include "measure/bulk_fraction.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace dilatant::bulk_fraction_test {
namespace {

World one_sphere(double z) {
  World w;
  w.box.length = Vec3(4.0, 5.0, 10.0);
  w.box.periodic = {true, true, false};
  w.bodies.add_sphere(0, Vec3(1.0, 1.0, z), 1.0, 1.0, false);
  return w;
}

TEST(SlabVolumeFraction, CountsTheExactPartOfEachSphereInsideTheSlab) {
  const double v = 4.0 / 3.0 * std::numbers::pi, slab = 4.0 * 5.0 * 4.0;
  // Wholly inside, cut through its centre, and a cap of height 0.5:
  // cap volume pi h^2 (3r - h)/3 = pi 0.25 * 2.5 / 3.
  EXPECT_NEAR(slab_volume_fraction(one_sphere(5.0), 3.0, 7.0), v / slab, 1e-15);
  EXPECT_NEAR(slab_volume_fraction(one_sphere(3.0), 3.0, 7.0), 0.5 * v / slab, 1e-15);
  EXPECT_NEAR(slab_volume_fraction(one_sphere(2.5), 3.0, 7.0),
              std::numbers::pi * 0.25 * 2.5 / 3.0 / slab, 1e-15);
  EXPECT_EQ(slab_volume_fraction(one_sphere(1.0), 3.0, 7.0), 0.0);
}

// Driven bodies (a boundary's, e.g. the shear cell's glued wall spheres) are
// not part of the suspension: the same sphere counts fully as a dynamic body
// and not at all as a driven one.
TEST(SlabVolumeFraction, LeavesOutDrivenBodies) {
  World w = one_sphere(5.0);
  const double v = 4.0 / 3.0 * std::numbers::pi, slab = 4.0 * 5.0 * 4.0;
  EXPECT_NEAR(slab_volume_fraction(w, 3.0, 7.0), v / slab, 1e-15);
  w.bodies.set_driven(0, 1);
  EXPECT_EQ(slab_volume_fraction(w, 3.0, 7.0), 0.0);
}

}  // namespace
}  // namespace dilatant::bulk_fraction_test
