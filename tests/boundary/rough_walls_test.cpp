// The shear cell's driven wall as a block of the time step (boundary/): its
// rigid-body motion under its drive and the contacts' impulses, against
// Newton's second law and momentum balance.
#include "boundary/rough_walls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::rough_walls_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// One top-wall sphere (infinite mass in the contact problems) at height z.
struct OneSphereWall {
  World world;
  RoughWalls walls;
};

OneSphereWall wall_sphere(double mass, double force, double velocity) {
  OneSphereWall w;
  w.world.bodies.add_sphere(0, Vec3(0.0, 0.0, 5.0), 1.0, 1.0, /*fixed=*/true);
  w.world.bodies.set_driven(0, kTopWall);
  w.walls = RoughWalls(
      SlidingWall{.spheres = {0}, .mass = mass, .drive_force = force, .velocity = velocity},
      CoulombLaw{.mu0 = 1.0, .eta_f = 0.0});
  return w;
}

// Alone, the wall accelerates as M dV/dt = F: V_n = V_0 + n dt F / M, and its
// spheres move with it (x = V dt summed, with the end-of-step velocity).
TEST(RoughWalls, AloneTheWallAcceleratesUnderItsDrive) {
  OneSphereWall w = wall_sphere(2.0, 3.0, 0.5);
  TimeStepper s(CoulombLaw{}, SolverSettings{}, 0.01);
  double x = 0.0;
  for (int n = 1; n <= 100; ++n) {
    s.step(w.world, &w.walls);
    const double v = 0.5 + n * 0.01 * 3.0 / 2.0;
    x += 0.01 * v;
    EXPECT_NEAR(w.walls.top().velocity, v, 4 * n * kEps);
    EXPECT_EQ(w.world.bodies.velocity[0], Vec3(w.walls.top().velocity, 0.0, 0.0));
    EXPECT_NEAR(w.world.bodies.position[0][0], x, 1e-12);
  }
  EXPECT_NEAR(w.walls.kinetic_energy(), 0.5 * 2.0 * std::pow(0.5 + 1.5, 2), 1e-12);
}

// A free sphere pressed under the wall by gravity pointing up (towards the
// wall), at rest: the x momentum of wall and sphere grows by exactly F dt per
// step (the drive is the only horizontal force), and the sphere, dragged by
// its top, rolls with the wall.
TEST(RoughWalls, DraggedSphereAndWallConserveTheDrivenMomentum) {
  OneSphereWall w = wall_sphere(3.0, 1.0, 0.0);
  w.world.gravity = Vec3(0.0, 0.0, 1.0);
  w.world.bodies.add_sphere(1, Vec3(0.0, 0.0, 3.0), 1.0, 1.0, false);
  const double m = w.world.bodies.mass(1), dt = 1e-3;
  TimeStepper s(CoulombLaw{}, SolverSettings{.tolerance = 1e-12}, dt);
  for (int n = 1; n <= 200; ++n) {
    s.step(w.world, &w.walls);
    const double momentum = 3.0 * w.walls.top().velocity + m * w.world.bodies.velocity[1][0];
    ASSERT_NEAR(momentum, n * dt * 1.0, 1e-9);
  }
  // Sticking (mu 1 against a push of m g), the sphere rolls under the wall:
  // its top point accelerates as F_t/m + r^2 F_t/I = (7/2) F_t/m, so it adds
  // the effective mass 2m/7 to the wall's: V(t) = F t / (M + 2m/7). The wall
  // runs ahead of the sphere's centre by ~(5/7) V t/2 ~ 3e-3 here, which tilts
  // the contact normal by ~2e-3 rad: the closed form holds to well within 1%.
  const double v_rolling = 0.2 / (3.0 + 2.0 * m / 7.0);
  EXPECT_NEAR(w.walls.top().velocity, v_rolling, 0.01 * v_rolling);
  EXPECT_EQ(s.contacts()[0].regime, Regime::Stick);
  ASSERT_EQ(s.contacts().size(), 1u);
  EXPECT_GT(s.contacts()[0].p_n, 0.0);
}

TEST(RoughWalls, ContactsOnTheTopWallObeyTheWallsLaw) {
  OneSphereWall w = wall_sphere(1.0, 1.0, 0.0);
  EXPECT_EQ(std::get<CoulombLaw>(w.walls.contact_law()).mu0, 1.0);
  w.walls.set_contact_law(CoulombLaw{.mu0 = 0.25, .eta_f = 0.0});
  EXPECT_EQ(std::get<CoulombLaw>(w.walls.contact_law()).mu0, 0.25);
  EXPECT_TRUE(w.world.bodies.is_driven(0));
}

}  // namespace
}  // namespace dilatant::rough_walls_test
