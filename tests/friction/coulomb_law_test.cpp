// Coulomb friction (constant mu0): the local tangential problem.
// A unit-mass sphere on a plane: w_t = 7/2, p_n = 0.01 over dt = 0.01, R_p = 2;
// the mu0 = 0.3 cone removes at most w_t mu0 p_n = 0.0105 of slip.
// Results are one or two correctly rounded operations: a few eps.
#include "friction/coulomb_law.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "friction/friction_law.hpp"

namespace dilatant::coulomb_law_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(CoulombLaw, MuIsConstant) {
  const CoulombLaw l{0.3, 0.5};
  EXPECT_EQ(l.mu(0.0), 0.3);
  EXPECT_EQ(l.mu(1.0), 0.3);
  EXPECT_EQ(friction_coefficient(FrictionLaw{l}, 123.0, 1.0), 0.3);
}

TEST(CoulombLaw, SticksInsideTheCone) {
  const TangentialSolution s = CoulombLaw{0.3, 0.5}.solve({0.0104, 3.5, 0.01, 0.01, 2.0});
  EXPECT_EQ(s.regime, Regime::Stick);  // 0.0104 < 0.0105: inside the cone
  EXPECT_NEAR(s.impulse, 0.0104 / 3.5, 4 * kEps * 0.003);
  EXPECT_EQ(s.sliding_speed, 0.0);
  EXPECT_EQ(s.sommerfeld, 0.0);
}

TEST(CoulombLaw, SlidesOutsideTheConeWithFullCone) {
  const double eta_f = 0.5;
  const TangentialSolution s = CoulombLaw{0.3, eta_f}.solve({0.05, 3.5, 0.01, 0.01, 2.0});
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.impulse, 0.3 * 0.01, 4 * kEps * 0.003);
  EXPECT_NEAR(s.sliding_speed, 0.05 - 0.0105, 4 * kEps * 0.05);
  // Reported s = eta_f v R_p / N with N = p_n / dt = 1; friction ignores it.
  EXPECT_NEAR(s.sommerfeld, eta_f * s.sliding_speed * 2.0, 4 * kEps * s.sommerfeld);
}

TEST(CoulombLaw, OpenContactCarriesNoFriction) {
  const TangentialSolution s = CoulombLaw{0.3, 0.5}.solve({0.05, 3.5, 0.0, 0.01, 2.0});
  EXPECT_EQ(s.regime, Regime::Open);
  EXPECT_EQ(s.impulse, 0.0);
  EXPECT_EQ(s.sliding_speed, 0.05);
}

}  // namespace
}  // namespace dilatant::coulomb_law_test
