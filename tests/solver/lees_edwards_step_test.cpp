// The time step across a Lees–Edwards boundary (geometry/periodic_box.hpp):
// a pair in contact through the boundary is the same mechanical problem as
// the same pair inside the box, seen from the partner's image; impulses still
// come in equal and opposite pairs, so momentum changes only by the image
// velocity a body picks up when it crosses.
#include <gtest/gtest.h>

#include <random>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::lees_edwards_step_test {
namespace {

constexpr double kDt = 1e-3;

World sheared_world(double offset, double velocity) {
  World w;
  w.box.length = Vec3(8.0, 6.0, 9.0);
  w.box.periodic = {true, true, true};
  w.box.lees_edwards = true;
  w.box.shear_offset = offset;
  w.box.shear_velocity = velocity;
  return w;
}

// Two spheres driven into each other obliquely (friction acts), once in the
// middle of the box and once with sphere 1 across the top boundary: stored at
// the bottom, x shifted back by the offset and its velocity by the copies'
// speed. The impulses, and the velocities the pair ends with (seen from the
// same copy), agree to round-off.
TEST(LeesEdwardsStep, APairThroughTheBoundaryTakesTheImpulseOfThePairInside) {
  const double offset = 3.3, speed = 1.7;
  const Vec3 x0(4.0, 3.0, 4.0), v0(0.3, 0.0, 0.9), v1(-0.2, 0.1, -0.8);
  const Vec3 x1 = x0 + Vec3(0.3, 0.2, 1.95);
  const CoulombLaw law{.mu0 = 0.4, .eta_f = 0.0};
  const SolverSettings settings{.tolerance = 1e-12, .max_iterations = 10000};

  World inside = sheared_world(offset, speed);
  inside.bodies.add_sphere(0, x0, 1.0, 1.0, false, v0);
  inside.bodies.add_sphere(1, x1, 1.0, 1.0, false, v1);

  // The same pair moved up so that sphere 1 lies beyond z = Lz, then stored
  // in the box: at the bottom, shifted by -offset, with v_x - speed.
  const Vec3 up(0.0, 0.0, 4.5);
  World across = sheared_world(offset, speed);
  across.bodies.add_sphere(0, x0 + up, 1.0, 1.0, false, v0);
  Vec3 y1 = x1 + up, w1 = v1;
  across.box.wrap_body(y1, w1);
  ASSERT_LT(y1[2], 2.0);  // really stored across the boundary, at the bottom
  across.bodies.add_sphere(1, y1, 1.0, 1.0, false, w1);

  TimeStepper a(law, settings, kDt), b(law, settings, kDt);
  a.step(inside);
  b.step(across);
  ASSERT_EQ(a.contacts().size(), 1u);
  ASSERT_EQ(b.contacts().size(), 1u);
  const Contact &ca = a.contacts()[0], &cb = b.contacts()[0];
  ASSERT_GT(ca.p_n, 0.0);
  EXPECT_GT(ca.p_t.norm(), 0.0);
  EXPECT_EQ(cb.image_drift, speed);  // sphere 0 meets sphere 1's copy one box up
  const double scale = ca.p_n + ca.p_t.norm();
  EXPECT_NEAR(cb.p_n, ca.p_n, 1e-10 * scale);
  EXPECT_NEAR((cb.p_t - ca.p_t).norm(), 0.0, 1e-10 * scale);
  EXPECT_NEAR((across.bodies.velocity[0] - inside.bodies.velocity[0]).norm(), 0.0, 1e-10);
  // Sphere 1 seen from sphere 0's copy: its velocity plus the copies' speed.
  EXPECT_NEAR(
      (across.bodies.velocity[1] + Vec3(speed, 0.0, 0.0) - inside.bodies.velocity[1]).norm(), 0.0,
      1e-10);
  EXPECT_NEAR((across.bodies.angular_velocity[1] - inside.bodies.angular_velocity[1]).norm(), 0.0,
              1e-10);
}

// A dense random packing with velocities in a sheared box, stepped many times:
// every impulse acts on two bodies with opposite signs, so the total momentum
// changes only when a body crosses z, by -k m V along x for k copies up.
TEST(LeesEdwardsStep, MomentumChangesOnlyByTheCrossingsImageVelocity) {
  World w = sheared_world(1.1, 0.9);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 150; ++n) {
    const Vec3 x(8.0 * u(rng), 6.0 * u(rng), 9.0 * u(rng));
    const Vec3 v(0.9 * (x[2] / 9.0 - 0.5) + 0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5),
                 0.3 * (u(rng) - 0.5));
    w.bodies.add_sphere(n, x, 0.5 + 0.1 * u(rng), 1.0, false, v);
  }
  TimeStepper stepper(CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, SolverSettings{}, 5e-3);
  Vec3 expected = w.bodies.momentum();
  int crossings = 0, contacts_across = 0;
  for (int step = 0; step < 400; ++step) {
    std::vector<double> z(w.bodies.size());
    for (std::size_t n = 0; n < z.size(); ++n) z[n] = w.bodies.position[n][2];
    stepper.step(w);
    for (const Contact& c : stepper.contacts())
      contacts_across += c.image_drift != 0.0 && c.p_n > 0;
    for (std::size_t n = 0; n < z.size(); ++n) {
      // Up through the top: z drops by ~Lz; down through the bottom: rises.
      const double jump = w.bodies.position[n][2] - z[n];
      const int k = jump < -4.5 ? 1 : (jump > 4.5 ? -1 : 0);
      if (k != 0) {
        ++crossings;
        expected[0] -= k * w.bodies.mass(n) * w.box.shear_velocity;
      }
    }
  }
  EXPECT_GE(crossings, 5);
  EXPECT_GE(contacts_across, 50);
  EXPECT_NEAR((w.bodies.momentum() - expected).norm(), 0.0,
              1e-9 * static_cast<double>(w.bodies.size()));
}

}  // namespace
}  // namespace dilatant::lees_edwards_step_test
