// Stokes drag (fluid/stokes_drag.hpp) through the whole time step, against the
// closed forms of a single sphere: sedimentation (terminal speed and exponential
// approach), the decay of its spin, and the ambient shear it is carried by.
// Time steps are far above the viscous relaxation time where only the limit is
// asserted, and below it where the approach is; tolerances are the backward-Euler
// error bound, |v_n - v(t_n)| <= (dt / 2 tau) max_x x e^-x v_inf < (dt / tau) v_inf / 5.
#include "fluid/stokes_drag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "fluid/suspending_fluid.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::stokes_drag_test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();

TimeStepper stepper(double dt) {
  return TimeStepper(CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, SolverSettings{}, dt);
}

SuspendingFluid stokes(double eta) { return SuspendingFluid(StokesDrag{.eta_f = eta}, {}); }

// m dv/dt = m g - 6 pi eta r v: v(t) = v_t (1 - exp(-t/tau)), v_t = m g / (6 pi eta r),
// tau = m / (6 pi eta r).
TEST(StokesDrag, SettlingSphereFollowsTheExponentialApproach) {
  World world;
  world.gravity = Vec3(0.0, 0.0, -9.81);
  world.bodies.add_sphere(0, Vec3::Zero(), 1e-3, 2500.0, false);  // a 1 mm glass bead
  const double eta = 1e-3, r = 1e-3, m = world.bodies.mass(0);    // in water
  const double zeta = 6.0 * kPi * eta * r, tau = m / zeta, v_t = -9.81 * m / zeta;
  const SuspendingFluid fluid = stokes(eta);
  const double dt = tau / 200.0;
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&fluid);
  for (int n = 1; n <= 1000; ++n) {
    s.step(world);
    const double exact = v_t * (1.0 - std::exp(-n * dt / tau));
    ASSERT_NEAR(world.bodies.velocity[0][2], exact, (dt / tau) * std::abs(v_t) / 5.0) << n;
  }
}

TEST(StokesDrag, TerminalSpeedIsExactForStepsFarAboveTheRelaxationTime) {
  World world;
  world.gravity = Vec3(0.0, 0.0, -1.0);
  world.bodies.add_sphere(0, Vec3::Zero(), 0.5, 1.0, false);
  const double eta = 2.0, m = world.bodies.mass(0), zeta = 6.0 * kPi * eta * 0.5;
  const SuspendingFluid fluid = stokes(eta);
  TimeStepper s = stepper(1e3 * m / zeta);  // dt = 1000 tau
  s.set_fluid_forces(&fluid);
  for (int n = 0; n < 5; ++n) s.step(world);
  EXPECT_NEAR(world.bodies.velocity[0][2], -m / zeta, 8 * kEps * m / zeta);
}

// I dw/dt = -8 pi eta r^3 w, I = 2/5 m r^2: w(t) = w0 exp(-t/tau_r).
TEST(StokesDrag, SpinningSphereDecaysExponentially) {
  World world;
  world.bodies.add_sphere(0, Vec3::Zero(), 0.7, 3.0, false, Vec3::Zero(), Vec3(0.0, 0.0, 4.0));
  const double eta = 0.1, r = 0.7, inertia = 0.4 * world.bodies.mass(0) * r * r;
  const double tau = inertia / (8.0 * kPi * eta * r * r * r);
  const SuspendingFluid fluid = stokes(eta);
  const double dt = tau / 100.0;
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&fluid);
  for (int n = 1; n <= 500; ++n) {
    s.step(world);
    ASSERT_NEAR(world.bodies.angular_velocity[0][2], 4.0 * std::exp(-n * dt / tau),
                (dt / tau) * 4.0 / 5.0)
        << n;
  }
  EXPECT_EQ(world.bodies.velocity[0], Vec3::Zero());  // spin alone: no translation
}

// A sphere at rest in simple shear U = (g (z - z0), 0, 0) ends moving with the
// fluid and spinning at half its vorticity, (0, g/2, 0): then it feels no force
// and no torque. Gravity-free; the step is far above both relaxation times.
TEST(StokesDrag, SphereIsCarriedByTheAmbientShear) {
  World world;
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 3.0), 1.0, 1.0, false);
  SuspendingFluid fluid = stokes(1.0);
  fluid.set_ambient({.shear_rate = 0.2, .z0 = 1.0});
  TimeStepper s = stepper(100.0 * world.bodies.mass(0) / (6.0 * kPi));
  s.set_fluid_forces(&fluid);
  for (int n = 0; n < 40; ++n) s.step(world);
  // It stays at z = 3, so U = 0.2 * 2 exactly in the limit.
  EXPECT_NEAR(world.bodies.velocity[0][0], 0.4, 1e-12);
  EXPECT_NEAR(world.bodies.velocity[0][2], 0.0, 1e-15);
  EXPECT_NEAR(world.bodies.angular_velocity[0][1], 0.1, 1e-12);
}

// Energy: KE(end) - KE(before drag) = drag work + contact work, step by step,
// for a sphere bouncing on a floor while it settles (both kinds act).
TEST(StokesDrag, DragAndContactWorksAddUpToTheKineticEnergyChange) {
  World world;
  world.gravity = Vec3(0.0, 0.0, -1.0);
  world.planes.push_back(Plane{});
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.2), 1.0, 1.0, false, Vec3(0.3, 0.0, -0.5),
                          Vec3(0.0, 1.0, 0.0));
  const SuspendingFluid fluid = stokes(0.05);
  TimeStepper s = stepper(0.01);
  s.set_fluid_forces(&fluid);
  int touching = 0;
  for (int n = 0; n < 300; ++n) {
    const StepReport r = s.step(world);
    const double scale = r.kinetic_energy_free + r.kinetic_energy + 1e-300;
    ASSERT_NEAR(r.kinetic_energy - r.kinetic_energy_free, r.drag_work + r.contact_work.total(),
                64 * kEps * scale)
        << n;
    ASSERT_LE(r.drag_work, 0.0);  // a fluid at rest only takes energy
    touching += r.contacts_closed > 0 ? 1 : 0;
  }
  EXPECT_GT(touching, 100);
}

}  // namespace
}  // namespace dilatant::stokes_drag_test
