// The fluid-force seam of the time step (fluid/fluid_forces.hpp): a drag linear
// in the end-of-step velocity, taken implicitly, against the closed forms of
// backward Euler, and together with a contact.
#include "fluid/implicit_drag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::implicit_drag_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The same drag on every body, the fluid at rest.
class UniformDrag final : public FluidForces {
 public:
  UniformDrag(double zeta, double xi) : zeta_(zeta), xi_(xi) {}
  void body_drag(const World& world, BodyDrag& drag) const override {
    drag.translational.assign(world.bodies.size(), zeta_);
    drag.rotational.assign(world.bodies.size(), xi_);
  }

 private:
  double zeta_, xi_;
};

TimeStepper stepper(double dt) {
  return TimeStepper(CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, SolverSettings{}, dt);
}

// m dv/dt = -zeta v with backward Euler: v_n = v_0 r^n, r = m / (m + dt zeta),
// exactly (to round-off), for any dt zeta / m: here 5, where forward Euler
// would diverge. The spin decays alike with I / (I + dt xi).
TEST(ImplicitDrag, FreeSphereDecaysAsBackwardEuler) {
  World world;
  world.bodies.add_sphere(0, Vec3::Zero(), 1.0, 1.0, false, Vec3(1.0, -2.0, 0.5),
                          Vec3(0.0, 3.0, 0.0));
  const double m = world.bodies.mass(0), inertia = 0.4 * m, dt = 0.1;
  const double zeta = 50.0 * m, xi = 20.0 * inertia;
  const UniformDrag drag(zeta, xi);
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&drag);
  const double r = m / (m + dt * zeta), q = inertia / (inertia + dt * xi);
  Vec3 x = Vec3::Zero();
  for (int n = 1; n <= 20; ++n) {
    s.step(world);
    const Vec3 v = Vec3(1.0, -2.0, 0.5) * std::pow(r, n);
    x += dt * v;
    EXPECT_NEAR((world.bodies.velocity[0] - v).norm(), 0.0, 8 * n * kEps * v.norm());
    EXPECT_NEAR(world.bodies.angular_velocity[0][1], 3.0 * std::pow(q, n),
                8 * n * kEps * 3.0 * std::pow(q, n));
    EXPECT_NEAR((world.bodies.position[0] - x).norm(), 0.0, 64 * kEps);
  }
  // The true masses are back after each step.
  EXPECT_EQ(world.bodies.mass(0), m);
}

// Sedimentation: m dv/dt = m g - zeta v. Backward Euler has the exact terminal
// velocity m g / zeta and reaches it as v_n = v_t (1 - r^n).
TEST(ImplicitDrag, SedimentingSphereReachesTheStokesTerminalVelocity) {
  World world;
  world.gravity = Vec3(0.0, 0.0, -9.81);
  world.bodies.add_sphere(0, Vec3::Zero(), 0.5, 2.0, false);
  const double m = world.bodies.mass(0), dt = 0.01, zeta = 3.0 * m;
  const UniformDrag drag(zeta, 0.0);
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&drag);
  const double v_terminal = -9.81 * m / zeta, r = m / (m + dt * zeta);
  for (int n = 1; n <= 2000; ++n) {
    s.step(world);
    const double expected = v_terminal * (1.0 - std::pow(r, n));
    ASSERT_NEAR(world.bodies.velocity[0][2], expected, 16 * n * kEps * std::abs(v_terminal));
  }
  EXPECT_NEAR(world.bodies.velocity[0][2], v_terminal, 1e-12 * std::abs(v_terminal));
}

// A sphere resting on a floor in a viscous fluid: the drag must not weaken the
// contact. With the effective mass m + dt zeta the Signorini solve gives
// exactly N = m g, and the sphere neither sinks nor moves.
TEST(ImplicitDrag, RestingSphereKeepsItsWeightOnTheFloor) {
  World world;
  world.gravity = Vec3(0.0, 0.0, -1.0);
  world.planes.push_back(Plane{});
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, false);
  const double m = world.bodies.mass(0), dt = 1e-2;
  const UniformDrag drag(10.0 * m, 10.0 * 0.4 * m);
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&drag);
  for (int n = 0; n < 50; ++n) s.step(world);
  ASSERT_EQ(s.contacts().size(), 1u);
  EXPECT_NEAR(s.contacts()[0].p_n / dt, m, 16 * kEps * m);
  EXPECT_NEAR(world.bodies.velocity[0].norm(), 0.0, 16 * kEps);
  EXPECT_NEAR(world.bodies.position[0][2], 1.0, 16 * kEps);
}

// Without fluid forces, or with a drag of zero, the step is the plain one, bit for bit.
TEST(ImplicitDrag, ZeroDragChangesNothing) {
  const auto fall = [](const FluidForces* fluid) {
    World world;
    world.gravity = Vec3(0.0, 0.0, -9.81);
    world.planes.push_back(Plane{});
    world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.2), 1.0, 1.0, false, Vec3(0.3, 0.0, 0.0));
    TimeStepper s = stepper(1e-3);
    s.set_fluid_forces(fluid);
    for (int n = 0; n < 300; ++n) s.step(world);
    return world.bodies;
  };
  const UniformDrag none(0.0, 0.0);
  const Bodies plain = fall(nullptr), dragged = fall(&none);
  EXPECT_EQ(plain.position[0], dragged.position[0]);
  EXPECT_EQ(plain.velocity[0], dragged.velocity[0]);
  EXPECT_EQ(plain.angular_velocity[0], dragged.angular_velocity[0]);
}

TEST(ImplicitDrag, RejectsCoefficientsThatDoNotMatchTheBodies) {
  Bodies b;
  b.add_sphere(0, Vec3::Zero(), 1.0, 1.0, false);
  b.add_sphere(1, Vec3(3.0, 0.0, 0.0), 1.0, 1.0, false);
  BodyDrag drag;
  drag.translational = {1.0};
  ImplicitDrag implicit;
  EXPECT_THROW(implicit.predict(drag, 0.1, b), std::invalid_argument);
}

}  // namespace
}  // namespace dilatant::implicit_drag_test
