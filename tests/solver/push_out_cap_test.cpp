// The cap on the push-out speed of overlaps (solver/local_problem.hpp,
// gap_rate()). A cold start of a 15 x 10 x 18 R cell at phi 0.64 (coulomb mu0 1,
// tolerance 1e-4) blew up without it: overlaps of 4e-3 R pushed out at |g|/dt
// while the automatic step fell from 0.148 to 7e-8 (docs/model.md "Overlap
// push-out"). The push-out must not grow as the step shrinks, and a gap that
// closes, or an overlap shallow enough, must be solved exactly as before.
#include <gtest/gtest.h>

#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant::push_out_cap_test {
namespace {

// A sphere of radius 1 resting on the plane z = 0 with its centre at z = 1 + gap,
// moving along the normal at `approach` (< 0: towards the plane).
struct OnePlane {
  World world;
  std::vector<Contact> contacts;
  OnePlane(double gap, double approach) {
    world.planes.push_back(Plane{});
    world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0 + gap), 1.0, 1.0, false,
                            Vec3(0.0, 0.0, approach));
    ContactDetector detector;
    detector.detect(world, 0.1, contacts);
  }
  double solve(double dt, double max_push_out) {
    SolverSettings settings;
    settings.max_push_out = max_push_out;
    solve_contacts(contacts, world.bodies, CoulombLaw{0.5, 0.0}, dt, settings);
    return world.bodies.velocity[0].z();
  }
};

TEST(PushOutCap, AnOverlapIsPushedOutNoFasterThanTheCap) {
  // Overlap 0.01: uncapped, a step of 1e-6 pushes it out at 1e4; capped at 0.1,
  // at 0.1, whatever the step.
  for (const double dt : {1e-2, 1e-4, 1e-6}) {
    OnePlane uncapped(-0.01, 0.0);
    ASSERT_EQ(uncapped.contacts.size(), 1u);
    EXPECT_NEAR(uncapped.solve(dt, kNoPushOutCap), 0.01 / dt, 1e-9 / dt);
    OnePlane capped(-0.01, 0.0);
    EXPECT_DOUBLE_EQ(capped.solve(dt, 0.1), 0.1) << "dt " << dt;
  }
}

TEST(PushOutCap, AShallowOverlapOrAClosingGapIsUntouched) {
  // |g|/dt = 0.05 < 0.1: removed within the step, as without the cap. (The gap
  // is taken from a centre at z = 1 + g: eps of round-off, eps/dt = 2e-14.)
  OnePlane shallow(-5e-4, 0.0);
  EXPECT_NEAR(shallow.solve(1e-2, 0.1), 0.05, 1e-13);
  // A gap of 0.01 approached at 3: stops exactly at contact (g + dt u_n = 0).
  OnePlane closing(0.01, -3.0);
  EXPECT_NEAR(closing.solve(1e-2, 0.1), -1.0, 1e-14);
}

TEST(PushOutCap, AnApproachingOverlapIsStillStopped) {
  // The cap limits how fast an overlap opens, never whether it may deepen: a
  // sphere overlapping by 0.5 and driven in at 100 leaves at the cap's 0.1.
  // (Cancelling an approach of 100 leaves 100 eps = 2e-14 of round-off.)
  OnePlane deep(-0.5, -100.0);
  EXPECT_NEAR(deep.solve(1e-6, 0.1), 0.1, 1e-13);
}

}  // namespace
}  // namespace dilatant::push_out_cap_test
