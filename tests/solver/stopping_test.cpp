// When the contact solve stops (solver/contact_solver.hpp, "When to stop"):
// a self-stress locked into a packing meets the relative-change test far from
// the answer, and cannot meet the residual test, which is scaled by the load.
//
// The packing: a column of N equal spheres between a floor and a ceiling,
// touching, under gravity g. Any uniform compression S of all N + 1 contacts
// is a self-stress (every sphere feels S from below and from above), so the
// solutions are p_k = S' + (N - k) m g dt for the contact below sphere k, with
// every sphere at rest. Warm-started with S = 1e6 m g dt and the spheres
// falling at g dt, one Gauss–Seidel pass from the floor up changes the impulses
// by at most N m g dt, a relative change of order N / (1e6 sqrt(N + 1)):
// the change test accepts it, while the weight has reached the floor only
// through the first contacts (a pass carries a correction one contact on).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "friction/coulomb_law.hpp"
#include "solver/contact_residual.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant::stopping_test {
namespace {

constexpr double kDt = 1e-3;
constexpr double kG = 1.0;
constexpr int kSpheres = 12;
constexpr double kSelfStress = 1e6;  // in units of m g dt

struct Column {
  World world;
  std::vector<Contact> contacts;  // floor first, then upwards, the ceiling last
  CoulombLaw law{.mu0 = 0.5, .eta_f = 0.0};
  double m = 0.0;

  Column() {
    world.planes.push_back(Plane{});
    world.planes.push_back(
        Plane{.point = Vec3(0.0, 0.0, 2.0 * kSpheres), .normal = -Vec3::UnitZ()});
    for (int k = 0; k < kSpheres; ++k)
      world.bodies.add_sphere(k, Vec3(0.0, 0.0, 1.0 + 2.0 * k), 1.0, 1.0, false,
                              Vec3(0.0, 0.0, -kG * kDt));
    m = world.bodies.mass(0);
    const Bodies& b = world.bodies;
    const auto plane_contact = [&](int body, int plane) {
      Contact c;
      c.i = body;
      c.other = -(plane + 1);
      c.normal = world.planes[static_cast<std::size_t>(plane)].normal;
      c.arm_i = 1.0;
      c.w_n = b.inv_mass[static_cast<std::size_t>(body)];
      c.w_t = c.w_n + 1.0 * 1.0 * 2.5 * c.w_n;  // r^2 / I = 5 / (2 m)
      c.reduced_radius = 1.0;
      return c;
    };
    contacts.push_back(plane_contact(0, 0));
    for (int k = 1; k < kSpheres; ++k) {  // sphere k on top of sphere k - 1
      Contact c;
      c.i = k;
      c.other = k - 1;
      c.normal = Vec3::UnitZ();
      c.arm_i = c.arm_j = 1.0;
      c.w_n = 2.0 / m;
      c.w_t = c.w_n + 2.0 * 2.5 / m;
      c.reduced_radius = 0.5;
      contacts.push_back(c);
    }
    contacts.push_back(plane_contact(kSpheres - 1, 1));
    // The warm start: the self-stress on every contact. It leaves every
    // sphere's velocity as it was (up to round-off).
    for (Contact& c : contacts) c.p_n = kSelfStress * m * kG * kDt;
    apply_impulses(contacts, world.bodies);
  }

  SolveReport solve(SolverSettings settings) {
    settings.reference_impulse =
        m * kG * kDt;  // the weight's impulse (drivers: weight_force times dt)
    return solve_contacts(contacts, world.bodies, law, kDt, settings);
  }
  double fastest() const {
    double v = 0.0;
    for (const Vec3& u : world.bodies.velocity) v = std::max(v, u.norm());
    return v;
  }
  ContactResidual residual() {
    const SlabPartition one = SlabPartition::single(contacts.size(), contacts.size());
    const SolverSettings settings{.reference_impulse = m * kG * kDt};
    return contact_residual({.contacts = contacts,
                             .slabs = one,
                             .bodies = world.bodies,
                             .law = law,
                             .dt = kDt,
                             .settings = settings});
  }
};

TEST(Stopping, ASelfStressMeetsTheRelativeChangeFarFromTheAnswer) {
  Column column;
  const SolveReport r = column.solve(
      {.convergence = Convergence::Change, .tolerance = 1e-4, .max_iterations = 10000});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  // Still falling at a large part of g dt: the weight is not carried yet.
  EXPECT_GT(column.fastest(), 0.3 * kG * kDt);
  // The residual, in units of the weight's impulse, says so.
  EXPECT_GT(column.residual().max(), 0.1);
}

// Every contact within tol m g dt of its local answer: a pair's relative
// normal speed is then at most tol m g dt w_n = 2 tol g dt, the floor's
// tol g dt, so sphere k, k pairs above the floor, moves at most
// (1 + 2k) tol g dt < 2N tol g dt.
TEST(Stopping, TheResidualTestHoldsTheColumnAtRestWithinItsTolerance) {
  Column column;
  const double tol = 1e-3;
  const SolveReport r = column.solve(
      {.convergence = Convergence::Residual, .tolerance = tol, .max_iterations = 20000});
  ASSERT_TRUE(r.converged);
  EXPECT_GT(r.iterations, 10);  // the weight took many passes to reach the floor
  EXPECT_LE(r.residual, tol);
  ASSERT_TRUE(r.final_residual_known);
  EXPECT_LE(column.residual().max(), tol);
  EXPECT_EQ(column.residual().max(), r.final_residual.max());  // the one evaluated is the final one
  EXPECT_LT(column.fastest(), 2.0 * kSpheres * tol * kG * kDt);
  // Force balance of the whole column: floor minus ceiling carries the weight.
  const double carried = column.contacts.front().p_n - column.contacts.back().p_n;
  EXPECT_NEAR(carried, kSpheres * column.m * kG * kDt, 2.0 * kSpheres * tol * column.m * kG * kDt);
  // The work counts every pass's visits and every residual evaluated: at
  // least the passes', and at most one evaluation for every pass.
  const double n = static_cast<double>(column.contacts.size());
  EXPECT_GT(r.contact_visits, n * r.iterations);
  EXPECT_LE(r.contact_visits, 2.0 * n * r.iterations);
}

// A tolerance below round-off cannot be met: the step ends at the pass cap,
// reported unconverged with the residual above the tolerance.
TEST(Stopping, AnUnreachableToleranceEndsUnconvergedAtTheCap) {
  Column column;
  const int cap = 200;
  const SolveReport r = column.solve(
      {.convergence = Convergence::Residual, .tolerance = 1e-12, .max_iterations = cap});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, cap);
  EXPECT_FALSE(r.final_residual_known);  // the last evaluation is not the final state's
  EXPECT_GT(column.residual().max(), 1e-12);
  // Evaluations are deferred 1, 2, 4, 8, then 16 passes after each failure:
  // at most 5 + (cap - 31) / 16 + 1 of them, each a visit per contact.
  const double n = static_cast<double>(column.contacts.size());
  EXPECT_LE(r.contact_visits / n - cap, 5.0 + (cap - 31.0) / kLongestDeferral + 1.0);
}

// The evaluation inside the solve's threads: the same passes, impulses and
// residual on one thread as on two (four slabs, red-black as in a run).
TEST(Stopping, TheResidualTestIsTheSameOnAnyNumberOfThreads) {
  std::vector<std::vector<double>> impulses;
  std::vector<int> passes;
  for (const int threads : {1, 2}) {
    Column column;
    SlabPartition slabs;  // four slabs of 3 or 4 contacts up the column
    slabs.begin = {0, 3, 6, 9, column.contacts.size()};
    slabs.boundary_begin = {3, 6, 9, column.contacts.size()};
    const SolverSettings settings{.convergence = Convergence::Residual,
                                  .tolerance = 1e-3,
                                  .reference_impulse = column.m * kG * kDt,
                                  .max_iterations = 20000,
                                  .threads = threads};
    const SolveReport r = solve_contacts({.contacts = column.contacts,
                                          .slabs = slabs,
                                          .bodies = column.world.bodies,
                                          .law = column.law,
                                          .dt = kDt,
                                          .settings = settings});
    EXPECT_TRUE(r.converged) << threads;
    passes.push_back(r.iterations);
    std::vector<double> p;
    for (const Contact& c : column.contacts) p.push_back(c.p_n);
    impulses.push_back(p);
  }
  EXPECT_EQ(passes[0], passes[1]);
  EXPECT_EQ(impulses[0], impulses[1]);
}

}  // namespace
}  // namespace dilatant::stopping_test
