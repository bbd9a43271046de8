// A sphere launched sliding (speed v0, no spin) on a horizontal plane with
// Coulomb friction mu.
//
// Closed form: while it slides, friction mu m g decelerates it and spins it up,
//     v(t) = v0 - mu g t,   r w(t) = 5/2 mu g t,   slip = v0 - 7/2 mu g t,
// so it starts rolling at t* = 2 v0 / (7 mu g) with v = 5/7 v0 (the angular
// momentum about the contact point, m r v + I w, is conserved), and then rolls
// at that constant speed (no rolling resistance in the model).
//
// What the scheme should give. Each step the free slip is the last step's slip
// (gravity is normal to the plane) and the sliding impulse is mu m g dt, so the
// slip falls by exactly 7/2 mu g dt per step: the grid values v(t_n) are exact,
// and the first sticking step is the first grid time at or after t*, i.e.
// t_roll - t* in [0, dt). The sticking step removes the remaining slip with an
// impulse parallel to the previous ones, which conserves m r v + I w as well, so
// the rolling speed is 5/7 v0 to round-off. Positions are the right Riemann sum
// of exact grid velocities: x_n - x(t_n) = dt/2 (v(t_n) - v0) up to the
// trapezoid error of the kink at t*, |Δslope| dt^2 / 8 = mu g dt^2 / 8.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::slide_to_roll_test {
namespace {

using scenes::kEps;

constexpr double kG = 9.81;
constexpr double kR = 0.4;
constexpr double kMu = 0.25;
constexpr double kV0 = 2.0;

void expect_slide_then_roll(double dt) {
  const double t_star = 2.0 * kV0 / (7.0 * kMu * kG);
  const int steps = static_cast<int>(std::lround(1.6 * t_star / dt));
  // Round-off of n steps of a few operations on numbers of size v0 (see incline_test).
  const double roundoff = 16.0 * steps * kEps * kV0;

  World world = scenes::world_with_plane(Vec3(0.0, 0.0, -kG));
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, kR), kR, 1.0, false, Vec3(kV0, 0.0, 0.0));
  TimeStepper stepper(CoulombLaw{kMu, 0.0}, SolverSettings{}, dt);

  double t_roll = -1.0, err_sliding = 0.0, err_rolling = 0.0, max_slip_rolling = 0.0;
  for (int n = 0; n < steps; ++n) {
    ASSERT_TRUE(stepper.step(world).solve.converged);
    const Contact* c = scenes::find_plane_contact(stepper.contacts(), 0);
    ASSERT_NE(c, nullptr);
    const double t = world.time;
    const Vec3& v = world.bodies.velocity[0];
    const Vec3& w = world.bodies.angular_velocity[0];
    if (t_roll < 0.0 && c->regime == Regime::Stick) t_roll = t;
    if (t_roll < 0.0) {
      ASSERT_EQ(c->regime, Regime::BoundaryLubricated) << "t = " << t;
      err_sliding = std::max(err_sliding, std::abs(v.x() - (kV0 - kMu * kG * t)));
      err_sliding = std::max(err_sliding, std::abs(kR * w.y() - 2.5 * kMu * kG * t));
    } else {
      ASSERT_EQ(c->regime, Regime::Stick) << "t = " << t;
      err_rolling = std::max(err_rolling, std::abs(v.x() - 5.0 / 7.0 * kV0));
      max_slip_rolling = std::max(max_slip_rolling, std::abs(v.x() - kR * w.y()));
    }
  }
  const std::string tag = "_dt_" + std::to_string(dt);
  scenes::record("roll_time_error" + tag, t_roll - t_star);
  scenes::record("sliding_velocity_error" + tag, err_sliding);
  scenes::record("rolling_velocity_error" + tag, err_rolling);
  ASSERT_GT(t_roll, 0.0) << "never started rolling";
  EXPECT_GE(t_roll - t_star, -roundoff / (3.5 * kMu * kG));
  EXPECT_LT(t_roll - t_star, dt);
  EXPECT_LE(err_sliding, roundoff);
  EXPECT_LE(err_rolling, roundoff);
  EXPECT_LE(max_slip_rolling, roundoff);

  // Position: right Riemann sum of exact grid velocities.
  const double T = world.time;
  const double x_exact =
      kV0 * t_star - 0.5 * kMu * kG * t_star * t_star + 5.0 / 7.0 * kV0 * (T - t_star);
  const double predicted = 0.5 * dt * (5.0 / 7.0 * kV0 - kV0);
  const double x_error = world.bodies.position[0].x() - x_exact;
  scenes::record("position_error" + tag, x_error);
  EXPECT_NEAR(x_error, predicted, kMu * kG * dt * dt / 8.0 + roundoff * T);
}

TEST(SlideToRoll, StartsRollingAtClosedFormTimeWithFiveSeventhsSpeed) {
  expect_slide_then_roll(1e-3);
  expect_slide_then_roll(1e-4);
}

}  // namespace
}  // namespace dilatant::slide_to_roll_test
