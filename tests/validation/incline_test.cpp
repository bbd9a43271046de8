// A sphere released from rest on an incline (Coulomb friction mu).
//
// Closed form (rigid body, contact at the lowest point, I = 2/5 m r^2):
//   rolls   when tan(theta) <= 7/2 mu:  a = 5/7 g sin(theta),      w r = v
//   slides  when tan(theta) >  7/2 mu:  a = g (sin(theta) - mu cos(theta)),
//                                        dw/dt = 5/2 mu g cos(theta) / r
//   and in both cases the normal force is N = m g cos(theta).
//
// We tilt gravity, g = g (sin(theta), 0, -cos(theta)), and keep the plane z = 0.
//
// What the scheme should give. Each step predicts v_free = v + dt g, so the
// free slip at the contact is (slip of the last step) + dt g sin(theta) and the
// normal impulse is exactly m g cos(theta) dt. With one contact the Gauss–Seidel
// solve is exact after one sweep. Sticking needs the impulse
// dt g sin(theta) / w_t = 2/7 m g sin(theta) dt, inside the cone mu m g cos(theta) dt
// iff tan(theta) <= 7/2 mu: the threshold is the continuous one, step by step.
// Implicit Euler is exact in the velocities for a constant acceleration, so the
// velocities must match the closed form to round-off, while the positions,
// x_n = dt sum_k v_k = a dt^2 n (n + 1) / 2, carry the first-order error
// x_n - a t^2 / 2 = a t dt / 2 exactly: we check that error and that it halves
// with dt.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::incline_test {
namespace {

using scenes::kEps;

constexpr double kG = 9.81;
constexpr double kR = 0.5;
constexpr double kMu = 0.2;  // threshold tan(theta_c) = 7/2 mu = 0.7, theta_c = 35.0 degrees

struct Sample {
  double t, x, v, w_y, slip, normal_force;
  Regime regime;
  bool converged;
};

std::vector<Sample> release_on_incline(double theta, double dt, int steps) {
  World world = scenes::world_with_plane(kG * Vec3(std::sin(theta), 0.0, -std::cos(theta)));
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, kR), kR, 1.0, false);
  TimeStepper stepper(CoulombLaw{kMu, 0.0}, SolverSettings{}, dt);
  std::vector<Sample> out;
  for (int n = 0; n < steps; ++n) {
    const StepReport report = stepper.step(world);
    const Contact* c = scenes::find_plane_contact(stepper.contacts(), 0);
    const Bodies& b = world.bodies;
    const Vec3 u =
        scenes::contact_point_velocity(b.velocity[0], b.angular_velocity[0], kR, Vec3::UnitZ());
    out.push_back(Sample{world.time, b.position[0].x(), b.velocity[0].x(),
                         b.angular_velocity[0].y(), u.x(), c ? c->p_n / dt : 0.0,
                         c ? c->regime : Regime::Open, report.solve.converged});
  }
  return out;
}

// Round-off bound for a quantity built up by n steps, each adding a few
// correctly rounded operations on numbers of size `scale`: 16 n eps scale
// (16 is a generous count of the operations per step: prediction, the free
// slip v - r w, the impulse, and its scatter to v and w).
double accumulated_roundoff(int n, double scale) { return 16.0 * n * kEps * scale; }

void expect_kinematics(double theta, bool rolls) {
  constexpr double dt = 1e-3;
  constexpr int steps = 1000;  // one second
  const double m = scenes::sphere_mass(kR);
  const double a =
      rolls ? 5.0 / 7.0 * kG * std::sin(theta) : kG * (std::sin(theta) - kMu * std::cos(theta));
  const double alpha = rolls ? a / kR : 2.5 * kMu * kG * std::cos(theta) / kR;
  const double v_max = a * steps * dt;
  const double n_exact = m * kG * std::cos(theta);

  const std::vector<Sample> run = release_on_incline(theta, dt, steps);
  double err_v = 0.0, err_w = 0.0, err_n = 0.0, max_slip = 0.0;
  for (int n = 0; n < steps; ++n) {
    const Sample& s = run[static_cast<std::size_t>(n)];
    ASSERT_TRUE(s.converged);
    ASSERT_EQ(s.regime, rolls ? Regime::Stick : Regime::BoundaryLubricated) << "step " << n;
    err_v = std::max(err_v, std::abs(s.v - a * s.t));
    err_w = std::max(err_w, std::abs(s.w_y - alpha * s.t) * kR);
    err_n = std::max(err_n, std::abs(s.normal_force - n_exact));
    max_slip = std::max(max_slip, std::abs(s.slip));
  }
  scenes::record("velocity_error", err_v);
  scenes::record("velocity_tolerance", accumulated_roundoff(steps, v_max));
  scenes::record("normal_force_rel_error", err_n / n_exact);
  scenes::record("max_slip_rolling", rolls ? max_slip : 0.0);
  EXPECT_LE(err_v, accumulated_roundoff(steps, v_max));
  EXPECT_LE(err_w, accumulated_roundoff(steps, v_max));
  // N = p_n/dt with p_n = m g cos(theta) dt from one division: a few eps.
  EXPECT_LE(err_n, 4.0 * kEps * n_exact);
  if (rolls) {
    // Sticking removes the free slip exactly each step, so no accumulation:
    // only the rounding of v - r w of size v_max remains.
    EXPECT_LE(max_slip, 16.0 * kEps * v_max);
  } else {
    // Slip grows as g (sin - 7/2 mu cos) t, i.e. (a - alpha r) t.
    const Sample& last = run.back();
    EXPECT_NEAR(last.slip, (a - alpha * kR) * last.t, accumulated_roundoff(steps, v_max));
    EXPECT_GT(last.slip, 0.0);
  }
}

// Position error of implicit Euler: exactly a t dt / 2, halving with dt.
void expect_first_order_positions(double theta, bool rolls) {
  const double a =
      rolls ? 5.0 / 7.0 * kG * std::sin(theta) : kG * (std::sin(theta) - kMu * std::cos(theta));
  constexpr double T = 0.5;
  double previous_error = 0.0;
  for (double dt : {2e-3, 1e-3, 5e-4}) {
    const int steps = static_cast<int>(std::lround(T / dt));
    const Sample s = release_on_incline(theta, dt, steps).back();
    const double error = s.x - 0.5 * a * s.t * s.t;
    // x_n - a t^2/2 = a t dt/2 exactly; round-off of the sum of n terms.
    EXPECT_NEAR(error, 0.5 * a * s.t * dt, accumulated_roundoff(steps, s.x));
    scenes::record("position_error_dt_" + std::to_string(dt), error);
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 2.0, 1e-6);
    }
    previous_error = error;
  }
}

// 2% on either side of the threshold: the per-step stick test compares
// dt g sin(theta) with 7/2 mu dt g cos(theta), whose difference (2%) is far
// above round-off, so the branch is unambiguous.
const double kThetaRoll = std::atan(3.5 * kMu * 0.98);
const double kThetaSlide = std::atan(3.5 * kMu * 1.02);

TEST(Incline, RollsBelowThreshold) { expect_kinematics(kThetaRoll, true); }
TEST(Incline, SlidesAboveThreshold) { expect_kinematics(kThetaSlide, false); }
TEST(Incline, RollingPositionIsFirstOrderInDt) { expect_first_order_positions(kThetaRoll, true); }
TEST(Incline, SlidingPositionIsFirstOrderInDt) { expect_first_order_positions(kThetaSlide, false); }

}  // namespace
}  // namespace dilatant::incline_test
