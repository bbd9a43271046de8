// The sediment's surface and bulk fraction on a packing whose answer is known
// in closed form: a simple cubic stack of unit spheres touching each other
// (centres on a lattice of spacing 2).
#include "measure/sediment_fraction.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace dilatant::sediment_fraction_test {
namespace {

World cubic_stack(int nx, int layers) {
  World w;
  w.box.length = Vec3(2.0 * nx, 2.0 * nx, 4.0 * layers);
  w.box.periodic = {true, true, false};
  for (int k = 0; k < layers; ++k)
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < nx; ++j)
        w.bodies.add_sphere(static_cast<std::int64_t>(w.bodies.size()),
                            Vec3(1.0 + 2.0 * i, 1.0 + 2.0 * j, 1.0 + 2.0 * k), 1.0, 1.0, false);
  return w;
}

TEST(SedimentFraction, SimpleCubicStack) {
  // 20 layers: the spheres reach z = 40. At height u from a layer's centres the
  // fraction is pi (1 - u^2) / 4 (one disc of radius sqrt(1 - u^2) per 2 x 2
  // cell); over a period it averages to pi/6, the plateau. The top slab
  // [39.5, 40] averages pi/4 (1 - 7/12) = 0.327 >= pi/12 (half the plateau),
  // so the surface is z_s = 40, and the bulk [4, 36] spans 16 whole periods:
  // exactly pi/6.
  const World w = cubic_stack(4, 20);
  const SedimentFraction f = sediment_fraction(w, 1.0, 4.0);
  EXPECT_DOUBLE_EQ(f.top, 40.0);
  EXPECT_DOUBLE_EQ(f.surface, 40.0);
  EXPECT_NEAR(f.phi, std::numbers::pi / 6.0, 1e-12);
  // An exclusion leaving [3, 37] (17 periods) is exact too.
  EXPECT_NEAR(sediment_fraction(w, 1.0, 3.0).phi, std::numbers::pi / 6.0, 1e-12);
}

TEST(SedimentFraction, EmptyWhenTheExclusionsMeet) {
  const World w = cubic_stack(2, 3);  // 6 tall: [4, 2] is empty
  EXPECT_EQ(sediment_fraction(w, 1.0, 4.0).phi, 0.0);
}

}  // namespace
}  // namespace dilatant::sediment_fraction_test
