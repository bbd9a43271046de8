// The conjugate-gradient acceleration of the sweeps (solver.acceleration = cg,
// solver/contact_solver.hpp): the same answer as plain Gauss–Seidel, reached in
// fewer sweeps where Gauss–Seidel is slow.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant::conjugate_gradient_test {
namespace {

// A column of n equal spheres resting on a floor under gravity g = 1: the k-th
// contact from the top carries the weight of the k spheres above it, so over
// one step p_n = k m g dt exactly. Gauss–Seidel passes the load down the column
// one contact per sweep and needs O(n^2) sweeps for it; it is the classic slow case.
struct Column {
  World world;
  std::vector<Contact> contacts;
  double m = 0.0;
  static constexpr double kDt = 1e-3;

  explicit Column(int n) {
    world.planes.push_back(Plane{});
    for (int k = 0; k < n; ++k) {
      world.bodies.add_sphere(k, Vec3(0.0, 0.0, 1.0 + 2.0 * k), 1.0, 1.0, false,
                              Vec3(0.0, 0.0, -kDt));  // one step of free fall from rest
    }
    m = world.bodies.mass(0);
    ContactDetector().detect(world, 0.1, contacts);
  }
  SolveReport solve(Acceleration a) {
    return solve_contacts(
        contacts, world.bodies, CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, kDt,
        SolverSettings{.tolerance = 1e-10, .max_iterations = 20000, .acceleration = a});
  }
};

TEST(ConjugateGradient, SameAnswerAsGaussSeidelInFewerSweeps) {
  const int n = 30;
  Column plain(n), accelerated(n);
  const SolveReport gs = plain.solve(Acceleration::None);
  const SolveReport cg = accelerated.solve(Acceleration::ConjugateGradient);
  ASSERT_TRUE(gs.converged);
  ASSERT_TRUE(cg.converged);
  RecordProperty("sweeps_gauss_seidel", gs.iterations);
  RecordProperty("sweeps_conjugate_gradient", cg.iterations);
  EXPECT_LT(cg.iterations, gs.iterations / 2) << gs.iterations << " vs " << cg.iterations;
  // Both meet the closed form: contact of sphere k (on the floor or on k - 1)
  // carries the n - k spheres from k up, within the tolerance's reach.
  const double w = plain.m * Column::kDt;
  for (const std::vector<Contact>* cs : {&plain.contacts, &accelerated.contacts}) {
    for (const Contact& c : *cs) {
      if (c.p_n <= 0.0 && c.gap > 1e-9) continue;
      const int lower = c.with_plane() ? -1 : std::min(c.i, c.other);
      const double expected = (n - 1 - lower) * w;
      EXPECT_NEAR(c.p_n, expected, 1e-6 * n * w) << "contact above sphere " << lower;
    }
  }
}

// One contact: Gauss–Seidel is exact after one sweep, and the acceleration
// must not disturb an answer that is already exact.
TEST(ConjugateGradient, OneContactStaysExact) {
  Column one(1);
  const SolveReport r = one.solve(Acceleration::ConjugateGradient);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 2);
  ASSERT_EQ(one.contacts.size(), 1u);
  EXPECT_NEAR(one.contacts[0].p_n, one.m * Column::kDt, 1e-15);
}

}  // namespace
}  // namespace dilatant::conjugate_gradient_test
