// The reduced radius of the Sommerfeld number (geometry/reduced_radius.hpp) and
// the Sommerfeld number itself (friction/sommerfeld.hpp): their limits.
#include "geometry/reduced_radius.hpp"

#include <gtest/gtest.h>

#include "friction/sommerfeld.hpp"

namespace dilatant::reduced_radius_test {
namespace {

TEST(ReducedRadius, EqualSpheresPlaneAndSymmetry) {
  EXPECT_DOUBLE_EQ(reduced_radius(0.9, 0.9), 0.9);      // r for two equal spheres
  EXPECT_DOUBLE_EQ(reduced_radius_on_plane(0.9), 1.8);  // 2r on a plane
  EXPECT_DOUBLE_EQ(reduced_radius(0.8, 1.0), reduced_radius(1.0, 0.8));
  // The plane is the limit r_j -> infinity of a sphere.
  EXPECT_NEAR(reduced_radius(0.9, 1e12), reduced_radius_on_plane(0.9), 1e-11);
}

// s = eta_f v R_p / N with N = p_n / dt (Fernandez et al. 2013, p. 2).
TEST(SommerfeldNumber, IsEtaSpeedRadiusOverNormalForce) {
  const double eta_f = 0.01, v = 2.0, r_p = 0.9, dt = 1e-3, p_n = 4e-3;  // N = 4
  const double k = sommerfeld_per_speed(eta_f, r_p, dt, p_n);
  EXPECT_DOUBLE_EQ(sommerfeld_number(k, v), eta_f * v * r_p / 4.0);
  EXPECT_EQ(sommerfeld_number(k, 0.0), 0.0);  // a sticking contact has s = 0
}

}  // namespace
}  // namespace dilatant::reduced_radius_test
