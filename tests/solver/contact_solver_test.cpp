// The Gauss–Seidel contact solver on problems small enough to solve by hand.
#include "solver/contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/coulomb_law.hpp"

namespace dilatant::contact_solver_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<Contact> detect(const World& world, double margin) {
  ContactDetector detector;
  std::vector<Contact> contacts;
  detector.detect(world, margin, contacts);
  return contacts;
}

TEST(ContactSolver, OneContactIsExactAfterOneSweep) {
  // Sphere touching a plane, approaching at 2 with slip 0.1: p_n = m 2 and the
  // slip is stopped (0.1 < 7/2 mu 2). The second sweep changes nothing.
  World world;
  world.planes.push_back(Plane{});
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, false, Vec3(0.1, 0.0, -2.0));
  std::vector<Contact> contacts = detect(world, 0.1);
  ASSERT_EQ(contacts.size(), 1u);
  const double m = world.bodies.mass(0);
  const SolveReport r =
      solve_contacts(contacts, world.bodies, CoulombLaw{0.5, 0.0}, 1e-3, SolverSettings{});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(r.residual, 0.0);
  EXPECT_NEAR(contacts[0].p_n, 2.0 * m, 4 * kEps * 2.0 * m);
  EXPECT_NEAR(contacts[0].p_t.x(), -2.0 / 7.0 * m * 0.1, 8 * kEps * m);
  EXPECT_EQ(contacts[0].regime, Regime::Stick);
}

TEST(ContactSolver, SeparatingContactCarriesNothing) {
  World world;
  world.planes.push_back(Plane{});
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, false, Vec3(1.0, 0.0, 0.5));
  std::vector<Contact> contacts = detect(world, 0.1);
  ASSERT_EQ(contacts.size(), 1u);
  const SolveReport r =
      solve_contacts(contacts, world.bodies, CoulombLaw{0.5, 0.0}, 1e-3, SolverSettings{});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(contacts[0].p_n, 0.0);
  EXPECT_EQ(contacts[0].regime, Regime::Open);
  EXPECT_EQ(world.bodies.velocity[0], Vec3(1.0, 0.0, 0.5));
}

// Regression (fixed in contact_solver.cpp): two spheres moving together fast,
// touching with a gap that rounds to -1e-16. The solver pushes the overlap out
// with an impulse of round-off size, so its relative change between sweeps is
// round-off divided by round-off and never fell below the tolerance: the solve
// ran all max_iterations sweeps and reported the step unconverged. With the
// round-off floor it converges at once.
TEST(ContactSolver, RoundOffLoadConverges) {
  World world;
  const Vec3 v(3.0, -2.0, 1.5);  // common velocity: nothing to do physically
  const Vec3 e = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Vec3 x0(0.3, 0.1, -0.2);
  world.bodies.add_sphere(0, x0, 1.0, 1.0, false, v);
  world.bodies.add_sphere(1, x0 + (1.6 - 1e-16) * e, 0.6, 1.0, false, v);
  std::vector<Contact> contacts = detect(world, 0.1);
  ASSERT_EQ(contacts.size(), 1u);
  ASSERT_LE(contacts[0].gap, 0.0);
  ASSERT_GE(contacts[0].gap, -1e-15);
  const SolveReport r =
      solve_contacts(contacts, world.bodies, CoulombLaw{0.3, 0.0}, 1e-3, SolverSettings{});
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 3);
  // The push-out is round-off: |p_n| ~ m |gap| / dt.
  EXPECT_LE(contacts[0].p_n, 10.0 * world.bodies.mass(0) * 1e-15 / 1e-3);
}

}  // namespace
}  // namespace dilatant::contact_solver_test
