// Squeeze-film lubrication (fluid/squeeze_film.hpp) through the whole time step:
// a sphere driven onto a plane or onto a fixed sphere through the film, against
// the ODE of the gap,
//
//     m dv/dt = F_ext - 6 pi eta a*^2 v / (h + delta),    dh/dt = v,
//
// integrated by RK4 far below every time scale. The step is far above the
// viscous relaxation time m/c (15x at the start, 2000x near contact), where an
// explicit film force would blow up. Its error: the film's resistance is taken
// at the gap of the step's start, so in the quasi-static regime h + delta
// shrinks by (1 - dt/T) per step instead of exp(-dt/T), T = 6 pi eta a*^2 / F:
// a relative error (t/T)(dt/T)/2, plus O(dt/T) from the start out of rest.
#include "fluid/squeeze_film.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "fluid/suspending_fluid.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::squeeze_film_test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kDelta = 1e-3;  // regularisation, in mean radii

TimeStepper stepper(double dt) {
  return TimeStepper(CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, SolverSettings{}, dt);
}

SuspendingFluid film(double eta) {
  return SuspendingFluid({}, SqueezeFilm{.eta_f = eta, .cutoff = 0.5, .regularization = kDelta});
}

// The ODE above, RK4 with step `h_step`, from rest at gap h0, advanced in place.
struct GapOde {
  double m, force, eta, a_star, delta;  // force > 0 pushes the surfaces together
  double h, v = 0.0, t = 0.0;
  double accel(double hh, double vv) const {
    return (-force - 6.0 * kPi * eta * a_star * a_star * vv / (std::max(hh, 0.0) + delta)) / m;
  }
  void advance_to(double t_end, double h_step) {
    const long n = std::lround((t_end - t) / h_step);
    for (long k = 0; k < n; ++k) {
      const double k1h = v, k1v = accel(h, v);
      const double k2h = v + 0.5 * h_step * k1v, k2v = accel(h + 0.5 * h_step * k1h, k2h);
      const double k3h = v + 0.5 * h_step * k2v, k3v = accel(h + 0.5 * h_step * k2h, k3h);
      const double k4h = v + h_step * k3v, k4v = accel(h + h_step * k3h, k4h);
      h += h_step / 6.0 * (k1h + 2.0 * k2h + 2.0 * k3h + k4h);
      v += h_step / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    }
    t += static_cast<double>(n) * h_step;
  }
};

// A light sphere (r = 1, rho 0.01) pulled down by g = 100 through the film of
// eta = 1 onto `world`'s partner below it, gap h0 = 0.3. Checks the gap against
// the ODE while the film acts, then that the sphere comes to rest on the
// partner with the contact carrying its weight.
void expect_gap_follows_the_ode(World& world, double a_star, double mean_radius, double gap_of_z) {
  const double g = 100.0, eta = 1.0, h0 = 0.3;
  world.gravity = Vec3(0.0, 0.0, -g);
  const std::size_t i = world.bodies.size() - 1;
  const double m = world.bodies.mass(i);
  GapOde ode{m, m * g, eta, a_star, kDelta * mean_radius, h0};
  const double t_film = 6.0 * kPi * eta * a_star * a_star / (m * g);  // T
  const double c0 = 6.0 * kPi * eta * a_star * a_star / (h0 + ode.delta);
  const double dt = 0.01 * t_film;
  ASSERT_GT(dt, 10.0 * m / c0);  // far above the viscous relaxation time
  const SuspendingFluid fluid = film(eta);
  TimeStepper s = stepper(dt);
  s.set_fluid_forces(&fluid);
  int checked = 0;
  for (int n = 1; n <= 400; ++n) {
    s.step(world);
    if (n % 50 != 0) continue;
    const double t = n * dt;
    ode.advance_to(t, 1e-4 * dt);  // RK4 well below m/c (> 2e-3 dt up to t = 4 T)
    const double gap = world.bodies.position[i][2] - gap_of_z;
    // The leading error (header), and a remainder bounded by dt / 4T.
    const double leading = -(t / t_film) * (dt / t_film) / 2.0;
    EXPECT_NEAR((gap + ode.delta) / (ode.h + ode.delta) - 1.0, leading, 0.25 * dt / t_film)
        << "t = " << t;
    ++checked;
  }
  EXPECT_EQ(checked, 8);
  // On to contact (h + delta falls by e per T; 0.3 -> 0 in ln(301) T ~ 5.7 T).
  for (int n = 0; n < 2000; ++n) s.step(world);
  const double gap = world.bodies.position[i][2] - gap_of_z;
  EXPECT_GE(gap, -16 * kEps);
  EXPECT_LT(gap, 1e-9);
  double normal = 0.0;
  for (const Contact& c : s.contacts()) normal += c.p_n + c.p_lub;
  EXPECT_NEAR(normal / dt, m * g, 1e-9 * m * g);
}

TEST(SqueezeFilm, SphereApproachesAPlaneAsTheOdeSays) {
  World world;
  world.planes.push_back(Plane{});
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.3), 1.0, 0.01, false);
  expect_gap_follows_the_ode(world, 1.0, 1.0, 1.0);
}

TEST(SqueezeFilm, SphereApproachesAFixedSphereAsTheOdeSays) {
  World world;
  world.bodies.add_sphere(0, Vec3::Zero(), 2.0, 1.0, true);  // fixed, r = 2
  world.bodies.add_sphere(1, Vec3(0.0, 0.0, 3.3), 1.0, 0.01, false);
  expect_gap_follows_the_ode(world, 2.0 / 3.0, 1.5, 3.0);
}

TEST(SqueezeFilm, ResistanceFollowsReynoldsWithinTheCutoff) {
  const SqueezeFilm f{.eta_f = 2.0, .cutoff = 0.5, .regularization = 1e-3};
  // Equal spheres r = 1: a* = 1/2, delta = 1e-3, 6 pi eta a*^2 / (h + delta).
  EXPECT_DOUBLE_EQ(f.resistance(0.1, 1.0, 1.0), 6.0 * kPi * 2.0 * 0.25 / 0.101);
  EXPECT_DOUBLE_EQ(f.resistance(-0.01, 1.0, 1.0), 6.0 * kPi * 2.0 * 0.25 / 1e-3);  // overlap
  EXPECT_EQ(f.resistance(0.5, 1.0, 1.0), 0.0);  // at the cut-off, in mean radii
  EXPECT_GT(f.resistance(0.5, 1.0, 1.2), 0.0);  // mean radius 1.1
  EXPECT_DOUBLE_EQ(f.resistance(0.2, 1.0, 0.0), 6.0 * kPi * 2.0 / 0.201);  // a plane: a* = r
}

// Two free spheres closing in through the film, no gravity: the film is an
// internal force, so the momentum is conserved to round-off; the approach slows
// without overlap; and the kinetic energy lost is the film's work, step by step.
TEST(SqueezeFilm, FreePairConservesMomentumAndAccountsForItsLoss) {
  World world;
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 0.0), 1.0, 1.0, false, Vec3(0.0, 0.0, 1.0));
  world.bodies.add_sphere(1, Vec3(0.3, 0.0, 2.2), 0.8, 1.0, false, Vec3(0.0, 0.0, -1.5));
  const auto momentum = [&] {
    return world.bodies.mass(0) * world.bodies.velocity[0] +
           world.bodies.mass(1) * world.bodies.velocity[1];
  };
  const Vec3 p0 = momentum();
  const SuspendingFluid fluid = film(0.5);
  TimeStepper s = stepper(0.01);
  s.set_fluid_forces(&fluid);
  double lost = 0.0;
  for (int n = 0; n < 300; ++n) {
    const StepReport r = s.step(world);
    EXPECT_NEAR((momentum() - p0).norm(), 0.0, 64 * kEps * p0.norm());
    EXPECT_NEAR(r.kinetic_energy - r.kinetic_energy_free, r.contact_work.total(),
                64 * kEps * r.kinetic_energy_free);
    EXPECT_LE(r.contact_work.lubrication, 0.0);
    lost -= r.contact_work.lubrication;
    EXPECT_LE(r.max_overlap, 1e-12);
  }
  EXPECT_GT(lost, 0.0);
}

}  // namespace
}  // namespace dilatant::squeeze_film_test
