// The Stribeck law (docs/model.md "Friction", paper Eq. 1): mu(s) on each branch, and each
// branch of the local tangential problem, StribeckLaw::solve.
//
// Reference values of mu_HD(s) = 2 pi s ln(5 / (6 pi s)) were computed
// independently (Python, double precision). Tolerances: mu is a log and three
// products, so it is correct to a few ulps; 8 eps relative.
#include "friction/stribeck_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "friction/friction_law.hpp"

namespace dilatant::stribeck_law_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

StribeckLaw law(double eta_f) { return StribeckLaw{0.3, 5e-5, 0.1, eta_f}; }

TEST(StribeckMu, BoundaryLubricatedBelowSc) {
  const StribeckLaw l = law(1.0);
  EXPECT_EQ(l.mu(0.0), 0.3);
  EXPECT_EQ(l.mu(1e-5), 0.3);
  EXPECT_EQ(l.mu(std::nextafter(5e-5, 0.0)), 0.3);
}

TEST(StribeckMu, HydrodynamicFromScToSlim) {
  const StribeckLaw l = law(1.0);
  EXPECT_NEAR(l.mu(5e-5), 0.002694366867682136, 8 * kEps * 0.0027);  // s = s_c is HD
  EXPECT_NEAR(l.mu(1e-3), 0.03506459634820459, 8 * kEps * 0.035);
  EXPECT_NEAR(l.mu(0.01), 0.2059702752337366, 8 * kEps * 0.21);
  EXPECT_NEAR(l.mu(0.05), 0.5242315439574966, 8 * kEps * 0.52);
  EXPECT_NEAR(StribeckLaw::hydrodynamic_mu(0.01), 0.2059702752337366, 8 * kEps * 0.21);
  EXPECT_EQ(friction_coefficient(FrictionLaw{l}, 0.01, 1.0), l.mu(0.01));
}

TEST(StribeckMu, CappedBeyondSlim) {
  const StribeckLaw l = law(1.0);
  const double cap = 0.6129458698542728;  // mu_HD(0.1), the cap of docs/model.md "Friction"
  EXPECT_NEAR(l.mu(0.1), cap, 8 * kEps * cap);
  EXPECT_EQ(l.mu(0.2), l.mu(0.1));
  EXPECT_EQ(l.mu(10.0), l.mu(0.1));
}

// A unit-mass sphere on a plane: w_t = 1/m + r^2/I = 7/2, p_n = 0.01 over
// dt = 0.01 (N = 1), R_p = 2 r = 2. Then k = eta_f R_p dt / p_n = 2 eta_f and
// the mu0 cone stops at most w_t mu0 p_n = 0.0105 of slip.
TangentialProblem problem(double free_slip) {
  return TangentialProblem{free_slip, 3.5, 0.01, 0.01, 2.0};
}

TEST(StribeckSolve, SticksInsideTheMu0Cone) {
  const TangentialSolution s = law(0.1).solve(problem(0.005));
  EXPECT_EQ(s.regime, Regime::Stick);
  EXPECT_DOUBLE_EQ(s.impulse, 0.005 / 3.5);  // exactly the impulse that stops the slip
  EXPECT_LE(s.impulse, 0.3 * 0.01);
  EXPECT_EQ(s.sliding_speed, 0.0);
  EXPECT_EQ(s.sommerfeld, 0.0);
}

TEST(StribeckSolve, SlidesOnBoundaryBranchWhenSBelowSc) {
  // BL answer: v = 0.02 - 0.0105 = 0.0095, s = 2 eta_f v = 1.9e-5 < s_c.
  const double eta_f = 1e-3;
  const TangentialSolution s = law(eta_f).solve(problem(0.02));
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.impulse, 0.3 * 0.01, 4 * kEps * 0.003);
  EXPECT_NEAR(s.sliding_speed, 0.0095, 4 * kEps * 0.02);
  EXPECT_NEAR(s.sommerfeld, 2.0 * eta_f * s.sliding_speed, 4 * kEps * 1.9e-5);
  EXPECT_LT(s.sommerfeld, 5e-5);
}

// Checks that an HD answer is the root of f(v) = v + w p_n mu(k v) - |u_t_free|
// to round-off, obeys the friction law |P_t| = mu(s) p_n, and has s >= s_c.
void expect_hd_root(const StribeckLaw& l, const TangentialProblem& p, const TangentialSolution& s) {
  const double k = l.eta_f * p.reduced_radius * p.dt / p.normal_impulse;
  const double wp = p.compliance * p.normal_impulse;
  EXPECT_EQ(s.regime, Regime::Hydrodynamic);
  EXPECT_GE(s.sommerfeld, l.s_c);
  EXPECT_NEAR(s.sommerfeld, k * s.sliding_speed, 4 * kEps * s.sommerfeld);
  // f(v) is a sum of terms of size free_slip, each rounded: a few eps.
  const double f = s.sliding_speed + wp * l.mu(k * s.sliding_speed) - p.free_slip;
  EXPECT_LE(std::abs(f), 8 * kEps * p.free_slip);
  EXPECT_NEAR(s.impulse, l.mu(s.sommerfeld) * p.normal_impulse,
              16 * kEps * p.free_slip / p.compliance);
  EXPECT_NEAR(s.impulse, (p.free_slip - s.sliding_speed) / p.compliance, 4 * kEps * s.impulse);
}

TEST(StribeckSolve, SlidesOnHydrodynamicBranchAtTheUniqueRoot) {
  // BL answer would give s = 0.2 * 0.0095 = 1.9e-3 >= s_c: HD.
  const StribeckLaw l = law(0.1);
  const TangentialProblem p = problem(0.02);
  const TangentialSolution s = l.solve(p);
  expect_hd_root(l, p, s);
  EXPECT_LT(s.sommerfeld, l.s_lim);
  // Slower friction than mu0 (mu_HD(2e-3 .. 4e-3) < 0.3): it slides faster than BL would.
  EXPECT_GT(s.sliding_speed, 0.0095);
  // f is increasing, so the root is unique: f changes sign across it.
  const double k = 0.2, wp = 0.035;
  auto f = [&](double v) { return v + wp * l.mu(k * v) - p.free_slip; };
  EXPECT_LT(f(s.sliding_speed * (1 - 1e-9)), 0.0);
  EXPECT_GT(f(s.sliding_speed * (1 + 1e-9)), 0.0);
}

TEST(StribeckSolve, HydrodynamicRootWithManyDecadesOfS) {
  // Across slips and viscosities the root must hold to round-off.
  for (double eta_f : {0.01, 0.1, 1.0, 3.0}) {
    for (double free_slip : {0.011, 0.02, 0.1, 1.0}) {
      const StribeckLaw l = law(eta_f);
      const TangentialProblem p = problem(free_slip);
      const TangentialSolution s = l.solve(p);
      SCOPED_TRACE(testing::Message() << "eta_f " << eta_f << " free_slip " << free_slip);
      if (s.regime == Regime::Hydrodynamic && s.sommerfeld < l.s_lim) {
        expect_hd_root(l, p, s);
      } else if (s.regime == Regime::Hydrodynamic) {
        // Beyond s_lim mu is the constant cap: v = free - w p_n mu(s_lim).
        EXPECT_NEAR(s.sliding_speed, free_slip - 0.035 * l.mu(l.s_lim), 8 * kEps * free_slip);
      } else {
        EXPECT_EQ(s.regime, Regime::BoundaryLubricated);  // only for tiny eta_f * slip
        EXPECT_LT(s.sommerfeld, l.s_c);
      }
    }
  }
}

TEST(StribeckSolve, CappedBeyondSlim) {
  // eta_f = 10: k = 20; free slip 1: even the capped friction leaves
  // v = 1 - 0.035 * 0.613 = 0.9785, s = 19.6 >> s_lim.
  const StribeckLaw l = law(10.0);
  const TangentialSolution s = l.solve(problem(1.0));
  EXPECT_EQ(s.regime, Regime::Hydrodynamic);
  EXPECT_GE(s.sommerfeld, l.s_lim);
  const double cap = 0.6129458698542728;
  EXPECT_NEAR(s.sliding_speed, 1.0 - 0.035 * cap, 8 * kEps);
  EXPECT_NEAR(s.impulse, cap * 0.01, 8 * kEps);
}

TEST(StribeckSolve, PrefersBoundaryBranchWhenBothAreConsistent) {
  // With eta_f = 2e-3 (k = 4e-3, v_c = s_c / k = 0.0125) and free slip 0.022:
  // BL gives v = 0.0115 < v_c, consistent. HD is consistent too: f(v_c) =
  // 0.0125 + 0.035 mu_HD(s_c) - 0.022 < 0 and f(free) > 0, so an HD root with
  // s >= s_c exists. The rule (docs/model.md "Friction") takes BL.
  const StribeckLaw l = law(2e-3);
  const TangentialProblem p = problem(0.022);
  const double v_c = l.s_c / 4e-3;
  ASSERT_LT(v_c + 0.035 * StribeckLaw::hydrodynamic_mu(l.s_c) - p.free_slip, 0.0);
  const TangentialSolution s = l.solve(p);
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.sliding_speed, 0.0115, 4 * kEps * 0.022);
}

// A contact that slid on the HD branch in the previous step
// (FrictionBranch::KeepHydrodynamic) keeps sliding on it while an HD answer
// with s >= s_c exists, even where rule 1 would stop it: eta_f = 0.1 (k = 0.2,
// v_c = 2.5e-4), free slip 0.005 lies inside the mu0 cone (0.0105), yet
// f(v_c) = 2.5e-4 + 0.035 mu_HD(s_c) - 0.005 < 0.
TEST(StribeckSolve, KeepsTheHydrodynamicBranchWhileItExists) {
  const StribeckLaw l = law(0.1);
  TangentialProblem p = problem(0.005);
  ASSERT_EQ(l.solve(p).regime, Regime::Stick);  // without memory: rule 1
  p.branch = FrictionBranch::KeepHydrodynamic;
  const TangentialSolution s = l.solve(p);
  expect_hd_root(l, p, s);
  EXPECT_GT(s.sliding_speed, 0.0);
}

// ... and falls back to rules 1-3 once the HD branch no longer exists: with
// eta_f = 1e-3 (k = 2e-3, v_c = 0.025) no HD answer with s >= s_c exists for a
// free slip of 0.02 < v_c, so the contact takes rule 2 (BL) as without memory.
TEST(StribeckSolve, LeavesTheHydrodynamicBranchBelowTheJump) {
  const StribeckLaw l = law(1e-3);
  TangentialProblem p = problem(0.02);
  p.branch = FrictionBranch::KeepHydrodynamic;
  const TangentialSolution s = l.solve(p);
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.sliding_speed, 0.0095, 4 * kEps * 0.02);
  p.free_slip = 0.005;  // and sticks where the cone holds it
  EXPECT_EQ(l.solve(p).regime, Regime::Stick);
}

TEST(StribeckSolve, OpenContactCarriesNoFriction) {
  TangentialProblem p = problem(0.02);
  p.normal_impulse = 0.0;
  const TangentialSolution s = law(0.1).solve(p);
  EXPECT_EQ(s.regime, Regime::Open);
  EXPECT_EQ(s.impulse, 0.0);
  EXPECT_EQ(s.sliding_speed, 0.02);
  EXPECT_EQ(s.sommerfeld, 0.0);
}

TEST(Regime, Names) {
  EXPECT_STREQ(regime_name(Regime::Open), "open");
  EXPECT_STREQ(regime_name(Regime::Stick), "stick");
  EXPECT_STREQ(regime_name(Regime::BoundaryLubricated), "bl");
  EXPECT_STREQ(regime_name(Regime::Hydrodynamic), "hd");
}

}  // namespace
}  // namespace dilatant::stribeck_law_test

// With mu0 below mu_HD(s_c) neither the BL nor the HD branch is consistent; the
// contact must slide exactly at s = s_c with a friction between the two.
TEST(StribeckLawJump, TinyMu0SlidesOnTheJump) {
  const dilatant::StribeckLaw law{0.001, 5e-5, 0.1, 1.0};
  const double mu_c = dilatant::StribeckLaw::hydrodynamic_mu(5e-5);
  ASSERT_GT(mu_c, 0.001);
  // k = eta R_p dt / p_n = 1e-3 -> v_c = s_c / k = 0.05. A free slip between
  // v_c + w p_n mu0 = 0.051 and v_c + w p_n mu_HD(s_c) = 0.0527 fails both branches.
  const dilatant::TangentialProblem p{0.052, 1.0, 1.0, 1e-3, 1.0};
  const auto sol = law.solve(p);
  EXPECT_DOUBLE_EQ(sol.sommerfeld, 5e-5);
  EXPECT_NEAR(sol.sliding_speed, 0.05, 1e-15);
  const double mu_eff = sol.impulse / p.normal_impulse;
  EXPECT_GE(mu_eff, 0.001);
  EXPECT_LE(mu_eff, mu_c);
}
