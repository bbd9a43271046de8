// The periodic box (geometry/periodic_box.hpp): images and wrapping per axis.
#include "geometry/periodic_box.hpp"

#include <gtest/gtest.h>

#include <random>

namespace dilatant::periodic_box_test {
namespace {

PeriodicBox cell_box() {
  PeriodicBox b;
  b.length = Vec3(10.0, 4.0, 7.0);
  b.periodic = {true, true, false};  // the shear cell: walls bound z
  return b;
}

TEST(PeriodicBox, MinimumImageCrossesPeriodicAxesOnly) {
  const PeriodicBox b = cell_box();
  // 9 apart in x is 1 apart through the boundary; z is not periodic.
  EXPECT_EQ(b.minimum_image(Vec3(9.5, 0.0, 6.5), Vec3(0.5, 0.0, 0.5)), Vec3(-1.0, 0.0, 6.0));
  EXPECT_EQ(b.minimum_image(Vec3(0.5, 3.5, 0.0), Vec3(0.5, 0.5, 0.0)), Vec3(0.0, -1.0, 0.0));
}

// On a periodic axis no component exceeds half the box; wrapping lands in [0, L).
TEST(PeriodicBox, ImagesAreNeverFartherThanHalfABox) {
  const PeriodicBox b = cell_box();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-30.0, 30.0);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 x(u(rng), u(rng), u(rng)), y(u(rng), u(rng), u(rng));
    const Vec3 d = b.minimum_image(x, y);
    for (int k = 0; k < 2; ++k) EXPECT_LE(std::abs(d[k]), 0.5 * b.length[k] + 1e-12);
    EXPECT_EQ(d[2], x[2] - y[2]);
    const Vec3 w = b.wrap(x);
    for (int k = 0; k < 2; ++k) {
      EXPECT_GE(w[k], 0.0);
      EXPECT_LT(w[k], b.length[k]);
      // The same point: an integer number of boxes away.
      const double boxes = (x[k] - w[k]) / b.length[k];
      EXPECT_NEAR(boxes, std::round(boxes), 1e-12);
    }
    EXPECT_EQ(w[2], x[2]);
  }
}

}  // namespace
}  // namespace dilatant::periodic_box_test
