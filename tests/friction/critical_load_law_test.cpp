// The critical-load law (friction/critical_load_law.hpp; Seto et al. 2013):
// each branch of the local tangential problem, the threshold itself, and the
// statuses a frozen branch imposes.
// A unit-mass sphere on a plane: w_t = 1/m + r^2/I = 7/2, dt = 0.01, R_p = 2;
// F* = 1, so the threshold impulse is F* dt = 0.01 (exact: 1 x 0.01). With
// p_n = 0.01 the mu0 = 0.3 cone removes at most w_t mu0 p_n = 0.0105 of slip.
// Results are one or two correctly rounded operations: a few eps.
#include "friction/critical_load_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "solver/local_problem.hpp"

namespace dilatant::critical_load_law_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kDt = 0.01;
constexpr double kThreshold = 0.01;  // F* dt

const CriticalLoadLaw kLaw{.mu0 = 0.3, .critical_load = 1.0, .eta_f = 0.5};

TangentialProblem problem(double free_slip, double normal_impulse,
                          FrictionBranch branch = FrictionBranch::Any) {
  return TangentialProblem{.free_slip = free_slip,
                           .compliance = 3.5,
                           .normal_impulse = normal_impulse,
                           .dt = kDt,
                           .reduced_radius = 2.0,
                           .branch = branch};
}

TEST(CriticalLoadMu, ZeroBelowTheCriticalLoadMu0FromIt) {
  EXPECT_EQ(kLaw.mu_at_load(0.0), 0.0);
  EXPECT_EQ(kLaw.mu_at_load(std::nextafter(1.0, 0.0)), 0.0);
  EXPECT_EQ(kLaw.mu_at_load(1.0), 0.3);  // closed on the frictional side
  EXPECT_EQ(kLaw.mu_at_load(7.0), 0.3);
  // The variant reads the load for this law, s for the others.
  EXPECT_EQ(friction_coefficient(FrictionLaw{kLaw}, 123.0, 0.5), 0.0);
  EXPECT_EQ(friction_coefficient(FrictionLaw{kLaw}, 0.0, 2.0), 0.3);
}

TEST(CriticalLoadSolve, OpenContactCarriesNoFriction) {
  const TangentialSolution s = kLaw.solve(problem(0.05, 0.0));
  EXPECT_EQ(s.regime, Regime::Open);
  EXPECT_EQ(s.impulse, 0.0);
  EXPECT_EQ(s.sliding_speed, 0.05);
}

TEST(CriticalLoadSolve, BelowTheCriticalLoadSlidesWithoutFriction) {
  // N = 0.5 F*, and a slip the mu0 cone of that load could stop: no friction at all.
  const double p_n = 0.5 * kThreshold;
  const TangentialSolution s = kLaw.solve(problem(0.001, p_n));
  EXPECT_EQ(s.regime, Regime::Frictionless);
  EXPECT_EQ(s.impulse, 0.0);
  EXPECT_EQ(s.sliding_speed, 0.001);
  // Reported s = eta_f v R_p / N with N = p_n / dt = 0.5; friction ignores it.
  EXPECT_NEAR(s.sommerfeld, 0.5 * 0.001 * 2.0 / 0.5, 4 * kEps * s.sommerfeld);
  EXPECT_STREQ(regime_name(Regime::Frictionless), "frictionless");
}

TEST(CriticalLoadSolve, AboveTheCriticalLoadSticksInsideTheCone) {
  const TangentialSolution s = kLaw.solve(problem(0.0104, kThreshold));
  EXPECT_EQ(s.regime, Regime::Stick);  // 0.0104 < 0.0105: inside the cone
  EXPECT_NEAR(s.impulse, 0.0104 / 3.5, 4 * kEps * 0.003);
  EXPECT_EQ(s.sliding_speed, 0.0);
  EXPECT_EQ(s.sommerfeld, 0.0);
}

TEST(CriticalLoadSolve, AboveTheCriticalLoadSlidesWithTheFullCone) {
  const double p_n = 2.0 * kThreshold;  // N = 2 F*: the cone removes 0.021
  const TangentialSolution s = kLaw.solve(problem(0.05, p_n));
  EXPECT_EQ(s.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(s.impulse, 0.3 * p_n, 4 * kEps * 0.006);
  EXPECT_NEAR(s.sliding_speed, 0.05 - 3.5 * 0.3 * p_n, 4 * kEps * 0.05);
  EXPECT_NEAR(s.sommerfeld, 0.5 * s.sliding_speed * 2.0 / 2.0, 4 * kEps * s.sommerfeld);
}

// At N = F* exactly the set-valued law allows any friction impulse in
// [0, min(mu0 p_n, |u_t_free|/w_t)]; the law takes the frictional end, so the
// local problem has one answer, and it jumps by the whole cone one ulp below.
TEST(CriticalLoadSolve, AtTheThresholdTheAnswerIsTheFrictionalOne) {
  const TangentialSolution at = kLaw.solve(problem(0.05, kThreshold));
  EXPECT_EQ(at.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(at.impulse, 0.3 * kThreshold, 4 * kEps * 0.003);
  const TangentialSolution below = kLaw.solve(problem(0.05, std::nextafter(kThreshold, 0.0)));
  EXPECT_EQ(below.regime, Regime::Frictionless);
  EXPECT_EQ(below.impulse, 0.0);
  // The same problem solved twice gives the same bits: no hidden state.
  EXPECT_EQ(kLaw.solve(problem(0.05, kThreshold)).impulse, at.impulse);
}

// Frozen statuses (solver/contact_solver.hpp "Frozen branches"): Boundary keeps
// the mu0 cone below F*, Frictionless keeps no friction above it; the Stribeck
// law's branches leave the threshold rule in charge.
TEST(CriticalLoadSolve, AFrozenStatusHoldsWhateverTheLoad) {
  const double below = 0.5 * kThreshold, above = 2.0 * kThreshold;
  const TangentialSolution kept = kLaw.solve(problem(0.05, below, FrictionBranch::Boundary));
  EXPECT_EQ(kept.regime, Regime::BoundaryLubricated);
  EXPECT_NEAR(kept.impulse, 0.3 * below, 4 * kEps * 0.0015);
  const TangentialSolution stuck = kLaw.solve(problem(0.001, below, FrictionBranch::Boundary));
  EXPECT_EQ(stuck.regime, Regime::Stick);
  const TangentialSolution free = kLaw.solve(problem(0.001, above, FrictionBranch::Frictionless));
  EXPECT_EQ(free.regime, Regime::Frictionless);
  EXPECT_EQ(free.impulse, 0.0);
  for (const FrictionBranch b : {FrictionBranch::Hydrodynamic, FrictionBranch::KeepHydrodynamic}) {
    EXPECT_EQ(kLaw.solve(problem(0.05, below, b)).regime, Regime::Frictionless);
    EXPECT_EQ(kLaw.solve(problem(0.05, above, b)).regime, Regime::BoundaryLubricated);
  }
}

// The solver freezes a contact's status from its regime (solver/local_problem.hpp).
TEST(CriticalLoadSolve, TheSolverFreezesEachStatusAsItsBranch) {
  Contact c;
  const auto frozen = [&c](Regime r) {
    c.regime = r;
    return imposed_branch(c, true);
  };
  EXPECT_EQ(frozen(Regime::Frictionless), FrictionBranch::Frictionless);
  EXPECT_EQ(frozen(Regime::Stick), FrictionBranch::Boundary);
  EXPECT_EQ(frozen(Regime::BoundaryLubricated), FrictionBranch::Boundary);
  // Before the freeze a frictionless contact of the last step imposes nothing.
  c.previous_regime = Regime::Frictionless;
  EXPECT_EQ(imposed_branch(c, false), FrictionBranch::Any);
}

}  // namespace
}  // namespace dilatant::critical_load_law_test
