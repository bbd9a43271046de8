// Lees–Edwards images (geometry/periodic_box.hpp): a body leaving through z
// re-enters shifted in x by the copies' offset and in velocity by their speed;
// the nearest image of a pair does not depend on which copy of either body
// the box holds.
#include <gtest/gtest.h>

#include <random>

#include "geometry/periodic_box.hpp"

namespace dilatant::lees_edwards_box_test {
namespace {

PeriodicBox sheared_box(double offset, double velocity) {
  PeriodicBox b;
  b.length = Vec3(10.0, 4.0, 7.0);
  b.periodic = {true, true, true};
  b.lees_edwards = true;
  b.shear_offset = offset;
  b.shear_velocity = velocity;
  return b;
}

TEST(LeesEdwardsBox, ABodyLeavingThroughTheTopReentersShiftedInPositionAndVelocity) {
  const PeriodicBox b = sheared_box(2.5, 0.8);
  Vec3 x(9.0, 1.0, 7.3), v(0.9, 0.1, 0.2);
  b.wrap_body(x, v);
  // One copy up: x - offset (wrapped in x), z - Lz, v_x - velocity.
  EXPECT_NEAR(x[0], 6.5, 1e-14);
  EXPECT_NEAR(x[2], 0.3, 1e-14);
  EXPECT_EQ(x[1], 1.0);
  EXPECT_NEAR(v[0], 0.1, 1e-15);
  EXPECT_EQ(v[1], 0.1);
  EXPECT_EQ(v[2], 0.2);
  // Through the bottom: the other way, wrapping x past 0 and Lx.
  Vec3 y(8.0, 1.0, -0.4), w(0.0, 0.0, -0.3);
  b.wrap_body(y, w);
  EXPECT_NEAR(y[0], 0.5, 1e-14);  // 8 + 2.5 - 10
  EXPECT_NEAR(y[2], 6.6, 1e-14);
  EXPECT_NEAR(w[0], 0.8, 1e-15);
}

TEST(LeesEdwardsBox, WithoutLeesEdwardsZWrapsAlone) {
  PeriodicBox b = sheared_box(2.5, 0.8);
  b.lees_edwards = false;
  Vec3 x(9.0, 1.0, 7.3), v(0.9, 0.1, 0.2);
  b.wrap_body(x, v);
  EXPECT_EQ(x[0], 9.0);
  EXPECT_EQ(v[0], 0.9);
  EXPECT_NEAR(x[2], 0.3, 1e-14);
}

// The separation of a pair and the velocity of the partner's image are
// properties of the sheared lattice of copies, not of the copy stored: wrap
// either body into any copy and nearest_image gives the same vector and the
// same image velocity.
TEST(LeesEdwardsBox, TheNearestImageDoesNotDependOnTheCopyStored) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 2000; ++n) {
    const PeriodicBox b = sheared_box(10.0 * u(rng), 2.0 * u(rng) - 1.0);
    // a near the top, b near the bottom: pairs across the boundary.
    const Vec3 xa(10.0 * u(rng), 4.0 * u(rng), 5.5 + 1.5 * u(rng));
    const Vec3 xb(10.0 * u(rng), 4.0 * u(rng), 1.5 * u(rng));
    const Vec3 va(u(rng), u(rng), u(rng)), vb(u(rng), u(rng), u(rng));
    const PeriodicBox::Image ref = b.nearest_image(xa, xb);
    const double image_speed = vb[0] + ref.image * b.shear_velocity;
    // b's copy one box up, as a body sees it before wrapping.
    Vec3 yb = xb + Vec3(b.shear_offset, 0.0, b.length[2]);
    Vec3 wb = vb + Vec3(b.shear_velocity, 0.0, 0.0);
    const PeriodicBox::Image up = b.nearest_image(xa, yb);
    EXPECT_NEAR((up.d - ref.d).norm(), 0.0, 1e-12);
    EXPECT_NEAR(wb[0] + up.image * b.shear_velocity, image_speed, 1e-12);
    b.wrap_body(yb, wb);
    EXPECT_NEAR((yb - xb).norm(), 0.0, 1e-12);
    EXPECT_NEAR((wb - vb).norm(), 0.0, 1e-12);
    // No component beyond half a box; the pair is across z here.
    EXPECT_LE(std::abs(ref.d[2]), 3.5 + 1e-12);
    EXPECT_LE(std::abs(ref.d[0]), 5.0 + 1e-12);
  }
}

TEST(LeesEdwardsBox, TheOffsetAdvancesWithTheShearAndStaysInTheBox) {
  PeriodicBox b = sheared_box(9.0, 3.0);
  b.advance_shear(0.5);
  EXPECT_NEAR(b.shear_offset, 0.5, 1e-14);
  b.shear_velocity = -3.0;
  b.advance_shear(0.5);
  EXPECT_NEAR(b.shear_offset, 9.0, 1e-14);
}

}  // namespace
}  // namespace dilatant::lees_edwards_box_test
