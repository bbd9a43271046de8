// Skipping open contacts between full sweeps (solver.skip_open_contacts,
// solver/contact_solver.hpp "Open contacts"): the same answer as visiting every
// contact in every sweep, with fewer local solves, including when a contact
// closes only after the full sweep that found it open.
#include <gtest/gtest.h>

#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant::skip_open_contacts_test {
namespace {

constexpr double kDt = 1e-3;

SolveReport solve(World& world, std::vector<Contact>& contacts, bool skip_open) {
  return solve_contacts(
      contacts, world.bodies, CoulombLaw{.mu0 = 0.5, .eta_f = 0.0}, kDt,
      SolverSettings{.tolerance = 1e-12, .max_iterations = 20000, .skip_open_contacts = skip_open});
}

// Two falling spheres above a floor, no gravity: B (below) reaches the floor
// within the step; A, a small gap above B and falling with it, closes that gap
// only once the floor has stopped B. The contacts are listed pairs first, so
// the first full sweep finds A-B open (A and B fall together) and only then
// stops B: A-B must be picked up by a later full sweep. Zero restitution gives
// the end velocities in closed form: each gap closes exactly,
//     v_B = -g_B / dt,   v_A = v_B - g_AB / dt.
TEST(SkipOpenContacts, AContactClosingAfterTheFullSweepIsPickedUp) {
  const double v = 1.0, g_b = 2e-4, g_ab = 3e-4;  // gaps close within dt at speed v
  for (const bool skip_open : {false, true}) {
    World world;
    world.planes.push_back(Plane{});
    world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0 + g_b), 1.0, 1.0, false, Vec3(0.0, 0.0, -v));
    world.bodies.add_sphere(1, Vec3(0.0, 0.0, 3.0 + g_b + g_ab), 1.0, 1.0, false,
                            Vec3(0.0, 0.0, -v));
    std::vector<Contact> contacts;
    ContactDetector().detect(world, 0.1, contacts);
    ASSERT_EQ(contacts.size(), 2u);
    const SolveReport r = solve(world, contacts, skip_open);
    ASSERT_TRUE(r.converged) << "skip_open " << skip_open;
    EXPECT_NEAR(world.bodies.velocity[0].z(), -g_b / kDt, 1e-9) << "skip_open " << skip_open;
    EXPECT_NEAR(world.bodies.velocity[1].z(), -(g_b + g_ab) / kDt, 1e-9)
        << "skip_open " << skip_open;
  }
}

// A column of 15 touching spheres on a floor under gravity, with 15 more
// spheres above it, each 0.05 above the one below (open contacts, all found
// by the detector's margin). Over one step the k-th contact from the top of the
// touching part carries the weight of the spheres above it in the column, the
// open ones nothing. Skipping them gives the same impulses in fewer visits.
TEST(SkipOpenContacts, SameImpulsesAsFullSweepsInFewerVisits) {
  const int touching = 15, n = 30;
  std::vector<double> p_full, p_skip;
  SolveReport full{}, skip{};
  double weight = 0.0;
  for (const bool skip_open : {false, true}) {
    World world;
    world.planes.push_back(Plane{});
    double z = 1.0;
    for (int k = 0; k < n; ++k) {
      world.bodies.add_sphere(k, Vec3(0.0, 0.0, z), 1.0, 1.0, false, Vec3(0.0, 0.0, -kDt));
      z += k + 1 < touching ? 2.0 : 2.05;
    }
    weight = world.bodies.mass(0) * kDt;
    std::vector<Contact> contacts;
    ContactDetector().detect(world, 0.1, contacts);
    ASSERT_EQ(contacts.size(), static_cast<std::size_t>(n));
    const SolveReport r = solve(world, contacts, skip_open);
    ASSERT_TRUE(r.converged);
    (skip_open ? skip : full) = r;
    for (const Contact& c : contacts) {
      const int lower = c.with_plane() ? -1 : std::min(c.i, c.other);
      const double expected = lower + 1 < touching ? (touching - 1 - lower) * weight : 0.0;
      EXPECT_NEAR(c.p_n, expected, 1e-8 * touching * weight) << "above sphere " << lower;
      (skip_open ? p_skip : p_full).push_back(c.p_n);
    }
  }
  EXPECT_DOUBLE_EQ(full.contact_visits, double(full.iterations) * n);
  EXPECT_LT(skip.contact_visits, 0.75 * full.contact_visits)
      << skip.contact_visits << " vs " << full.contact_visits;
  for (std::size_t k = 0; k < p_full.size(); ++k)
    EXPECT_NEAR(p_skip[k], p_full[k], 1e-8 * touching * weight);
}

}  // namespace
}  // namespace dilatant::skip_open_contacts_test
