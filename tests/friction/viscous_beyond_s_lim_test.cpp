// friction.beyond_s_lim = "viscous" (friction/stribeck_law.hpp): beyond s_lim the
// friction continues as mu(s_lim) s / s_lim, i.e. a force linear in the sliding
// speed, F_t = mu(s_lim) eta_f R_p v_s / s_lim, whatever the load.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "friction/stribeck_law.hpp"

namespace dilatant::viscous_beyond_s_lim_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kCap = 0.6129458698542728;  // mu_HD(0.1)

StribeckLaw viscous(double eta_f) {
  return StribeckLaw{
      .mu0 = 0.3, .s_c = 5e-5, .s_lim = 0.1, .eta_f = eta_f, .viscous_beyond_s_lim = true};
}

TEST(ViscousBeyondSlim, ContinuousAtSlimAndLinearBeyond) {
  const StribeckLaw l = viscous(1.0);
  EXPECT_NEAR(l.mu(0.1), kCap, 8 * kEps * kCap);
  EXPECT_NEAR(l.mu(std::nextafter(0.1, 0.0)), kCap, 1e-12);
  EXPECT_NEAR(l.mu(0.2), 2.0 * kCap, 16 * kEps * kCap);
  EXPECT_NEAR(l.mu(3.0), 30.0 * kCap, 64 * kEps * kCap);
  EXPECT_EQ(l.mu(0.01), StribeckLaw::hydrodynamic_mu(0.01));  // unchanged below s_lim
}

// A unit-mass sphere on a plane sliding fast (stribeck_law_test.cpp's problem):
// w_t = 7/2, p_n = 0.01 over dt = 0.01, R_p = 2, eta_f = 1, so s = 2 v. The
// viscous force makes the impulse 0.2 mu_cap v and v = u_free / (1 + 0.7 mu_cap),
// where the cap would give v = u_free - 3.5 mu_cap p_n.
TEST(ViscousBeyondSlim, FastSlidingContactCarriesAViscousForce) {
  const TangentialProblem p{1.0, 3.5, 0.01, 0.01, 2.0};
  const TangentialSolution s = viscous(1.0).solve(p);
  const double v = 1.0 / (1.0 + 0.7 * kCap);
  EXPECT_EQ(s.regime, Regime::Hydrodynamic);
  EXPECT_NEAR(s.sliding_speed, v, 1e-12);
  EXPECT_NEAR(s.sommerfeld, 2.0 * v, 1e-12);
  // F_t = impulse / dt = mu_cap eta_f R_p v / s_lim.
  EXPECT_NEAR(s.impulse / 0.01, kCap * 1.0 * 2.0 * v / 0.1, 1e-10);
  StribeckLaw capped = viscous(1.0);
  capped.viscous_beyond_s_lim = false;
  EXPECT_NEAR(capped.solve(p).sliding_speed, 1.0 - 3.5 * kCap * 0.01, 1e-12);
}

// The force does not depend on the load: doubling p_n changes s but not F_t.
TEST(ViscousBeyondSlim, ForceIndependentOfTheLoad) {
  const TangentialSolution light = viscous(1.0).solve(TangentialProblem{1.0, 3.5, 0.01, 0.01, 2.0});
  const TangentialSolution heavy = viscous(1.0).solve(TangentialProblem{1.0, 3.5, 0.02, 0.01, 2.0});
  EXPECT_NEAR(light.impulse, heavy.impulse, 1e-12);
  EXPECT_NEAR(light.sliding_speed, heavy.sliding_speed, 1e-12);
}

}  // namespace
}  // namespace dilatant::viscous_beyond_s_lim_test
