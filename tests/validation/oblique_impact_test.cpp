// Oblique impact of a sphere on a plane, zero restitution, Coulomb mu, no gravity.
//
// The sphere touches the plane (gap 0) and moves with v = v_t t + (-v_n) n,
// t a unit tangent, without spin. Over one step the normal impulse m v_n stops
// the normal motion (no rebound) and the cone holds mu m v_n of tangential
// impulse. Stopping the slip needs v_t / w_t = 2/7 m v_t (w_t = 7/(2m)), so
//   sticks iff v_t <= 7/2 mu v_n:  v_t' = 5/7 v_t,  r w' = 5/7 v_t (n x t),
//                                  contact point velocity 0;
//   slides otherwise:              v_t' = v_t - mu v_n,  r w' = 5/2 mu v_n (n x t).
// This is one exact local solve (one contact, one sweep), so the result must
// equal the closed form to round-off: a few eps of the velocities involved.
// We use a tilted plane and a tangent off the axes so that every vector
// component is exercised.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::oblique_impact_test {
namespace {

using scenes::kEps;

constexpr double kR = 0.7;
constexpr double kMu = 0.4;  // threshold v_t / v_n = 7/2 mu = 1.4
constexpr double kVn = 1.5;
constexpr double kDt = 1e-3;

struct Impact {
  Vec3 n, t;  // plane normal and tangent of the incoming slip
  Vec3 v, w;  // after one step
  Regime regime;
};

Impact impact(double v_t) {
  const Vec3 n = Vec3(0.3, -0.2, 1.0).normalized();
  const Vec3 t = n.cross(Vec3(1.0, 2.0, 0.5)).normalized();
  const Vec3 point(0.5, -1.0, 2.0);
  World world = scenes::world_with_plane(Vec3::Zero(), point, n);
  world.bodies.add_sphere(0, point + kR * n, kR, 1.0, false, v_t * t - kVn * n);
  TimeStepper stepper(CoulombLaw{kMu, 0.0}, SolverSettings{}, kDt);
  EXPECT_TRUE(stepper.step(world).solve.converged);
  const Contact* c = scenes::find_plane_contact(stepper.contacts(), 0);
  EXPECT_NE(c, nullptr);
  return Impact{n, t, world.bodies.velocity[0], world.bodies.angular_velocity[0],
                c ? c->regime : Regime::Open};
}

// Round-off: a handful of operations on velocities of size |v| and on the
// normalised n and t, 16 eps (v_t + v_n); and the gap, computed from positions
// of size |x| ~ 3 and so zero only to ~eps |x|, which the solver pushes out at
// gap/dt: 8 eps |x| / dt.
double tolerance(double v_t) { return 16.0 * kEps * (v_t + kVn) + 8.0 * kEps * 3.0 / kDt; }

TEST(ObliqueImpact, SticksBelowThreshold) {
  const double v_t = 0.95 * 3.5 * kMu * kVn;  // 5% inside the cone: far above round-off
  const Impact s = impact(v_t);
  const double tol = tolerance(v_t);
  EXPECT_EQ(s.regime, Regime::Stick);
  EXPECT_NEAR(s.v.dot(s.n), 0.0, tol);  // no rebound, no penetration
  EXPECT_LE((s.v - 5.0 / 7.0 * v_t * s.t).norm(), tol);
  EXPECT_LE((kR * s.w - 5.0 / 7.0 * v_t * s.n.cross(s.t)).norm(), tol);
  EXPECT_LE(scenes::contact_point_velocity(s.v, s.w, kR, s.n).norm(), tol);
  scenes::record("velocity_error", (s.v - 5.0 / 7.0 * v_t * s.t).norm());
  scenes::record("contact_point_speed", scenes::contact_point_velocity(s.v, s.w, kR, s.n).norm());
}

TEST(ObliqueImpact, SlidesAboveThreshold) {
  const double v_t = 1.05 * 3.5 * kMu * kVn;
  const Impact s = impact(v_t);
  const double tol = tolerance(v_t);
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.v.dot(s.n), 0.0, tol);
  EXPECT_LE((s.v - (v_t - kMu * kVn) * s.t).norm(), tol);
  EXPECT_LE((kR * s.w - 2.5 * kMu * kVn * s.n.cross(s.t)).norm(), tol);
  // Still slipping, in the original direction, at v_t - 7/2 mu v_n.
  const Vec3 u = scenes::contact_point_velocity(s.v, s.w, kR, s.n);
  EXPECT_LE((u - (v_t - 3.5 * kMu * kVn) * s.t).norm(), tol);
  scenes::record("velocity_error", (s.v - (v_t - kMu * kVn) * s.t).norm());
}

TEST(ObliqueImpact, ExactlyAtThresholdSticksWithFullCone) {
  // At v_t = 7/2 mu v_n both answers coincide: the contact point stops and the
  // impulse is exactly the cone. Either regime label is acceptable here.
  const double v_t = 3.5 * kMu * kVn;
  const Impact s = impact(v_t);
  const double tol = tolerance(v_t);
  EXPECT_LE((s.v - 5.0 / 7.0 * v_t * s.t).norm(), tol);
  EXPECT_LE(scenes::contact_point_velocity(s.v, s.w, kR, s.n).norm(), tol);
}

}  // namespace
}  // namespace dilatant::oblique_impact_test
