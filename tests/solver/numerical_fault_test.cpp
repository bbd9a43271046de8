// Numerical faults are detected and named (issue 19, item 5; docs/model.md
// "Overlaps and numerical faults"): a non-finite body stops the step with its
// id, and the step reports which contact holds the largest overlap, the same
// whatever the number of threads.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::numerical_fault_test {
namespace {

TEST(NumericalFault, ANonFiniteBodyStopsTheStepNamingItsId) {
  World w;
  w.bodies.add_sphere(10, Vec3(0.0, 0.0, 0.0), 1.0, 1.0, false);
  w.bodies.add_sphere(42, Vec3(5.0, 0.0, 0.0), 1.0, 1.0, false);
  w.bodies.velocity[1][1] = std::numeric_limits<double>::quiet_NaN();
  TimeStepper stepper(CoulombLaw{}, SolverSettings{}, 1e-3);
  try {
    stepper.step(w);
    FAIL() << "a NaN velocity went through a step";
  } catch (const NumericalFault& fault) {
    const std::string what = fault.what();
    EXPECT_NE(what.find("body 1 (id 42)"), std::string::npos) << what;
    EXPECT_NE(what.find("non-finite"), std::string::npos) << what;
  }
  // An infinite spin alike; a finite state passes.
  w.bodies.velocity[1][1] = 0.0;
  w.bodies.position[1] = Vec3(5.0, 0.0, 0.0);
  stepper.step(w);
  w.bodies.angular_velocity[0][2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(stepper.step(w), NumericalFault);
}

// Three pairs overlapping by 2^-10, 2^-8 and 2^-8 (and one open), at
// positions exact in binary and with no push-out, so that the two deepest tie
// exactly: the step names the first, for 1 and 3 threads.
TEST(NumericalFault, TheLargestOverlapIsLocatedAtItsContact) {
  for (const int threads : {1, 3}) {
    World w;
    w.box.length = Vec3(100.0, 100.0, 100.0);
    const double overlaps[] = {0x1p-10, 0x1p-8, 0x1p-8, -0.5};
    for (int p = 0; p < 4; ++p) {
      const Vec3 x(8.0 * p, 0.0, 0.0);
      w.bodies.add_sphere(2 * p, x, 1.0, 1.0, true);
      w.bodies.add_sphere(2 * p + 1, x + Vec3(2.0 - overlaps[p], 0.0, 0.0), 1.0, 1.0, false);
    }
    TimeStepper stepper(CoulombLaw{}, SolverSettings{.threads = threads, .max_push_out = 0.0},
                        1e-3);
    const StepReport r = stepper.step(w);
    ASSERT_GE(r.max_overlap_contact, 0);
    const Contact& c = stepper.contacts()[static_cast<std::size_t>(r.max_overlap_contact)];
    EXPECT_EQ(std::min(c.i, c.other), 2) << threads << " threads";  // the pair of bodies 2, 3
    EXPECT_EQ(r.max_overlap, 0x1p-8);
  }
}

}  // namespace
}  // namespace dilatant::numerical_fault_test
