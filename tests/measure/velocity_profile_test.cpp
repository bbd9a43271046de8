// The velocity profile across the gap (measure/velocity_profile.hpp): binned,
// time-weighted, walls left out, and its least-squares line.
#include "measure/velocity_profile.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dilatant::velocity_profile_test {
namespace {

// Spheres at heights z with v_x = g z + c; optionally a wall sphere moving fast.
World linear_flow(double g, double c, bool with_wall) {
  World w;
  for (int k = 0; k < 20; ++k) {
    const double z = 0.25 + 0.5 * k;
    w.bodies.add_sphere(k, Vec3(1.0, 1.0, z), 0.2, 1.0, false, Vec3(g * z + c, 0.0, 0.0));
  }
  if (with_wall) w.bodies.add_sphere(99, Vec3(1.0, 1.0, 5.0), 0.2, 1.0, true);
  if (with_wall) w.bodies.velocity.back() = Vec3(1000.0, 0.0, 0.0);
  if (with_wall) w.bodies.set_driven(w.bodies.size() - 1, 2);
  return w;
}

TEST(VelocityProfile, LinearFlowGivesItsSlopeExactly) {
  VelocityProfile p(10.0, 10);
  const World w = linear_flow(0.3, -0.7, true);
  p.add(w, 0.5);
  p.add(w, 1.5);  // time weights: the mean per bin is unchanged
  const LinearFit f = p.fit(0.0, 10.0);
  EXPECT_NEAR(f.slope, 0.3, 1e-13);
  EXPECT_NEAR(f.intercept, -0.7, 1e-12);
  EXPECT_LE(f.max_deviation, 1e-12);
  // Two spheres per bin, weight 2 each: 4 per bin in all, the wall counted nowhere.
  for (int k = 0; k < p.bins(); ++k)
    EXPECT_DOUBLE_EQ(p.weights()[static_cast<std::size_t>(k)], 4.0);
  // A window fits only its own bins.
  EXPECT_NEAR(p.fit(2.0, 6.0).slope, 0.3, 1e-13);
}

TEST(VelocityProfile, DeviationFromALineIsReported) {
  VelocityProfile p(4.0, 4);
  World w;
  const double v[4] = {0.0, 1.0, 1.0, 0.0};  // a tent: best line is flat at 0.5
  for (int k = 0; k < 4; ++k)
    w.bodies.add_sphere(k, Vec3(0.0, 0.0, 0.5 + k), 0.2, 1.0, false, Vec3(v[k], 0.0, 0.0));
  p.add(w, 1.0);
  const LinearFit f = p.fit(0.0, 4.0);
  EXPECT_NEAR(f.slope, 0.0, 1e-15);
  EXPECT_NEAR(f.intercept, 0.5, 1e-15);
  EXPECT_NEAR(f.max_deviation, 0.5, 1e-15);
  // Fewer than two bins: no line.
  EXPECT_EQ(p.fit(0.0, 1.0).slope, 0.0);
}

}  // namespace
}  // namespace dilatant::velocity_profile_test
