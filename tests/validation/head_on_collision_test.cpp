// Head-on, zero-restitution collision of two unequal spheres (no gravity).
//
// Closed form: perfectly inelastic, so both end with the centre-of-mass velocity
//     V = (m1 v1 + m2 v2) / (m1 + m2),
// momentum is conserved, and the kinetic energy lost is
//     dE = 1/2 m1 m2 / (m1 + m2) |v1 - v2|^2.
//
// What the scheme should give. The spheres start apart (gap g0). In the step
// where they would cross, the Signorini condition g + dt u_n >= 0 lets them
// close the gap exactly (relative normal velocity -g/dt); in the next step the
// gap is 0 and the remaining relative velocity is removed. Impulses act in
// equal and opposite pairs, so momentum is conserved to round-off at every
// step. The only thing not exact is the end-of-step gap, which is 0 up to the
// rounding of the positions, eps |x|; the next step turns that into a relative
// velocity of at most eps |x| / dt (the push-out term -g/dt). That sets the
// tolerance on "common velocity" and on "no rebound": a few eps |x| / dt plus a
// few eps |v|.
#include <gtest/gtest.h>

#include <cmath>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::head_on_collision_test {
namespace {

using scenes::kEps;

TEST(HeadOnCollision, UnequalSpheresStickWithCentreOfMassVelocity) {
  constexpr double dt = 1e-3;
  const double r1 = 1.0, r2 = 0.6, g0 = 0.0137;
  const Vec3 e = Vec3(1.0, 2.0, 2.0) / 3.0;  // line of centres, off the axes
  const Vec3 v1 = 1.3 * e, v2 = -0.8 * e;
  const Vec3 x1(0.2, -0.1, 0.3);
  const Vec3 x2 = x1 + (r1 + r2 + g0) * e;

  World world;
  world.bodies.add_sphere(0, x1, r1, 1.0, false, v1);
  world.bodies.add_sphere(1, x2, r2, 1.0, false, v2);
  const double m1 = world.bodies.mass(0), m2 = world.bodies.mass(1);
  const Vec3 p0 = world.bodies.momentum();
  const Vec3 V = p0 / (m1 + m2);
  const double e0 = world.bodies.kinetic_energy();
  const double de_exact = 0.5 * m1 * m2 / (m1 + m2) * (v1 - v2).squaredNorm();

  TimeStepper stepper(CoulombLaw{0.3, 0.0}, SolverSettings{}, dt);
  const double x_scale = x2.norm() + 0.1;  // positions stay below this size over the run
  const double v_tol = 8.0 * kEps * x_scale / dt + 8.0 * kEps * (v1.norm() + v2.norm());
  const double p_tol = 8.0 * kEps * (m1 * v1.norm() + m2 * v2.norm());

  int first_contact_step = -1;
  double max_dp = 0.0, max_separation_rate = -1.0, max_gap_error = 0.0;
  for (int n = 0; n < 40; ++n) {
    const StepReport rep = stepper.step(world);
    ASSERT_TRUE(rep.solve.converged) << "step " << n << ", residual " << rep.solve.residual;
    const Bodies& b = world.bodies;
    max_dp = std::max(max_dp, (b.momentum() - p0).norm());
    const Contact* c = scenes::find_pair_contact(stepper.contacts(), 0, 1);
    if (first_contact_step < 0 && c != nullptr && c->p_n > 0.0) first_contact_step = n;
    if (first_contact_step >= 0) {
      // Touching from the end of the first contact step on: no overlap, no gap.
      const double gap = (b.position[1] - b.position[0]).norm() - r1 - r2;
      max_gap_error = std::max(max_gap_error, std::abs(gap));
      max_separation_rate = std::max(max_separation_rate, (b.velocity[1] - b.velocity[0]).dot(e));
    }
    if (first_contact_step >= 0 && n > first_contact_step) {
      EXPECT_LE((b.velocity[0] - V).norm(), v_tol) << "step " << n;
      EXPECT_LE((b.velocity[1] - V).norm(), v_tol) << "step " << n;
    }
  }
  ASSERT_GE(first_contact_step, 0) << "the spheres never collided";
  // The gap closes at relative speed 2.1 in steps of 2.1e-3: contact in step 7.
  EXPECT_EQ(first_contact_step, static_cast<int>(std::ceil(g0 / (2.1 * dt))) - 1);
  EXPECT_LE(max_dp, p_tol);
  EXPECT_LE(max_separation_rate, v_tol);
  EXPECT_LE(max_gap_error, 8.0 * kEps * x_scale);
  const double de = e0 - world.bodies.kinetic_energy();
  // dE from velocities known to v_tol: |d(KE)| <= (m1 + m2) |V| v_tol.
  EXPECT_NEAR(de, de_exact, (m1 + m2) * V.norm() * v_tol + 8.0 * kEps * e0);
  scenes::record("momentum_error", max_dp);
  scenes::record("energy_loss_rel_error", std::abs(de - de_exact) / de_exact);
  scenes::record("max_separation_rate", max_separation_rate);
  scenes::record("velocity_tolerance", v_tol);
}

}  // namespace
}  // namespace dilatant::head_on_collision_test
