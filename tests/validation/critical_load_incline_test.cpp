// A sphere released from rest on an incline under the critical-load law
// (friction/critical_load_law.hpp): the load just below and just above the
// critical load F*, branch by branch.
//
// Closed form (rigid body, contact at the lowest point, I = 2/5 m r^2, normal
// force N = m g cos(theta)):
//   N <  F*                      frictionless: a = g sin(theta), w = 0
//   N >= F*, tan(theta) <= 7/2 mu0  rolls:      a = 5/7 g sin(theta), w r = v
//   N >= F*, tan(theta) >  7/2 mu0  slides:     a = g (sin(theta) - mu0 cos(theta)),
//                                               dw/dt = 5/2 mu0 g cos(theta) / r
// F* is held and the load moved by gravity's magnitude, g = (1 -+ 2%) g*, with
// m g* cos(theta) = F*; the angles are 2% either side of the rolling threshold
// (tests/validation/incline_test.cpp). Each step's normal impulse is exactly
// m g cos(theta) dt (one contact: the solve is exact after one pass), so
// N = p_n/dt is 2% from F*, far above round-off: every step takes one branch.
// Implicit Euler is exact in the velocities under a constant acceleration, so
// they match the closed form to the round-off of n steps, 16 n eps v_max.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "friction/critical_load_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::critical_load_incline_test {
namespace {

using scenes::kEps;

constexpr double kR = 0.5;
constexpr double kMu0 = 0.2;  // rolling threshold tan(theta_c) = 7/2 mu0 = 0.7
constexpr double kCriticalLoad = 3.0;
constexpr double kDt = 1e-3;
constexpr int kSteps = 1000;

const double kThetaRoll = std::atan(3.5 * kMu0 * 0.98);
const double kThetaSlide = std::atan(3.5 * kMu0 * 1.02);

// The gravity that loads the contact with `load_ratio` x F* at angle theta.
double gravity_for(double load_ratio, double theta) {
  return load_ratio * kCriticalLoad / (scenes::sphere_mass(kR) * std::cos(theta));
}

struct Expected {
  Regime regime;
  double a, alpha;  // acceleration along the incline, angular acceleration
};

Expected closed_form(double g, double theta) {
  const double n = scenes::sphere_mass(kR) * g * std::cos(theta);
  if (n < kCriticalLoad) return {Regime::Frictionless, g * std::sin(theta), 0.0};
  if (std::tan(theta) <= 3.5 * kMu0) {
    const double a = 5.0 / 7.0 * g * std::sin(theta);
    return {Regime::Stick, a, a / kR};
  }
  return {Regime::BoundaryLubricated, g * (std::sin(theta) - kMu0 * std::cos(theta)),
          2.5 * kMu0 * g * std::cos(theta) / kR};
}

void expect_release(double load_ratio, double theta, Regime regime) {
  const double g = gravity_for(load_ratio, theta);
  const Expected e = closed_form(g, theta);
  ASSERT_EQ(e.regime, regime);  // the case is the one the test names
  World world = scenes::world_with_plane(g * Vec3(std::sin(theta), 0.0, -std::cos(theta)));
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, kR), kR, 1.0, false);
  TimeStepper stepper(CriticalLoadLaw{.mu0 = kMu0, .critical_load = kCriticalLoad, .eta_f = 0.0},
                      SolverSettings{}, kDt);
  const double v_max = e.a * kSteps * kDt;
  const double roundoff = 16.0 * kSteps * kEps * v_max;
  const double n_exact = scenes::sphere_mass(kR) * g * std::cos(theta);
  double err_v = 0.0, err_w = 0.0, err_n = 0.0;
  for (int n = 0; n < kSteps; ++n) {
    ASSERT_TRUE(stepper.step(world).solve.converged);
    const Contact* c = scenes::find_plane_contact(stepper.contacts(), 0);
    ASSERT_NE(c, nullptr);
    ASSERT_EQ(c->regime, regime) << "step " << n;
    const Bodies& b = world.bodies;
    err_v = std::max(err_v, std::abs(b.velocity[0].x() - e.a * world.time));
    err_w = std::max(err_w, std::abs(b.angular_velocity[0].y() - e.alpha * world.time) * kR);
    err_n = std::max(err_n, std::abs(c->p_n / kDt - n_exact));
  }
  scenes::record("velocity_error", err_v);
  scenes::record("velocity_tolerance", roundoff);
  EXPECT_LE(err_v, roundoff);
  EXPECT_LE(err_w, roundoff);
  EXPECT_LE(err_n, 4.0 * kEps * n_exact);  // p_n = m g cos dt, then one division
  if (regime == Regime::Frictionless) {
    // Never a tangential impulse: the sphere does not turn at all.
    EXPECT_EQ(world.bodies.angular_velocity[0].norm(), 0.0);
  }
}

// Just below F*: frictionless at an angle where Coulomb friction would roll it,
// so it slides at the full g sin(theta) where 2% more load rolls it at 5/7 of that.
TEST(CriticalLoadIncline, BelowTheCriticalLoadSlidesFreely) {
  expect_release(0.98, kThetaRoll, Regime::Frictionless);
  expect_release(0.98, kThetaSlide, Regime::Frictionless);
}
TEST(CriticalLoadIncline, AboveTheCriticalLoadRollsBelowTheCoulombAngle) {
  expect_release(1.02, kThetaRoll, Regime::Stick);
}
TEST(CriticalLoadIncline, AboveTheCriticalLoadSlidesWithMu0AboveTheCoulombAngle) {
  expect_release(1.02, kThetaSlide, Regime::BoundaryLubricated);
}

}  // namespace
}  // namespace dilatant::critical_load_incline_test
