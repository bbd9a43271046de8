// Rule 6's rate_falls (curve_analysis.hpp): a stress ramp whose rate falls from
// one point to the next, above the onset, by more than the points' combined
// noise is DST, as a ramp stepping across the turning point of an S-shaped flow
// curve does; a noisy curve whose rate never falls is not, at a false-call rate
// bounded by 1 - confidence.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/curve_analysis.hpp"
#include "analysis/synthetic_curves.hpp"

namespace dilatant::analysis::rate_falls_test {
namespace {

using test::CurveModel;

FlowPoint simulated(double tau, double rate, double rate_err) {
  FlowPoint p;
  p.shear_stress = tau;
  p.shear_rate = rate;
  p.viscosity = tau / rate;
  p.shear_rate_err = rate_err;
  return p;
}

// A simulated stress ramp, stresses a decade apart: a Newtonian branch, then
// thickening with eta ∝ gamma_dot (Bagnold, rate ∝ tau^(1/2)), each rate known
// to 4% (one standard error, the size of a sweep point's over 4 strain).
FlowCurve thickening_ramp() {
  FlowCurve c;
  c.source = "ramp.csv";
  c.sample = "mu0=0.4";
  c.phi = 0.61;
  constexpr double kEta = 70.0, kOnset = 1.0, kErr = 0.04;
  for (int k = -2; k <= 4; ++k) {
    const double tau = std::pow(10.0, k);
    const double rate = tau <= kOnset ? tau / kEta : kOnset / kEta * std::sqrt(tau / kOnset);
    c.points.push_back(simulated(tau, rate, kErr * rate));
  }
  return c;
}

TEST(RateFalls, ARampThatStepsOntoTheFrictionalBranchIsDst) {
  FlowCurve ramp = thickening_ramp();
  const CurveResult before = analyse_curve(ramp, AnalysisSettings{});
  ASSERT_EQ(before.regime, Regime::Cst);  // Bagnold to the top: n = 1
  // The next stress, 10x higher, flows 5.7x more slowly (the decisive study's
  // mu0 0.4 at tau 1e5): eta jumps 57x for 10x the stress.
  const double top_rate = ramp.points.back().shear_rate / 5.7;
  ramp.points.push_back(simulated(1e5, top_rate, 0.04 * top_rate));
  const CurveResult r = analyse_curve(ramp, AnalysisSettings{});
  EXPECT_EQ(r.regime, Regime::Dst);
  EXPECT_EQ(r.dst_evidence, DstEvidence::RateFalls);
  EXPECT_EQ(dst_evidence_name(r.dst_evidence), "rate_falls");
  EXPECT_EQ(r.fall_stress, 1e5);  // the point on the lower branch
  EXPECT_TRUE(std::isnan(before.fall_stress));
  // The window's power law is still reported, finite (the rule does not need it).
  EXPECT_TRUE(std::isfinite(r.n));
  // On the lower branch the rate grows again (the decisive study's tau 1e6:
  // 2.1x the rate at 1e5). The window's power law then turns over (rule 6's
  // rate_not_increasing decides first) and the fall is still found where it
  // happened.
  ramp.points.push_back(simulated(1e6, 2.1 * top_rate, 0.04 * 2.1 * top_rate));
  const CurveResult on = analyse_curve(ramp, AnalysisSettings{});
  EXPECT_EQ(on.regime, Regime::Dst);
  EXPECT_EQ(on.dst_evidence, DstEvidence::RateNotIncreasing);
  EXPECT_EQ(on.fall_stress, 1e5);
}

// The rule's threshold: one-sided at a false-call rate of 1e-3 shared by the m
// steps above the onset (m <= 7 here): z = 3.09 (m = 1) to 3.63 (m = 7). A fall
// of half the smallest stays, one of twice the largest is DST, whatever the
// points' own noise (the combined noise of two points is sqrt(2) err).
TEST(RateFalls, AFallWithinTheNoiseIsNotDst) {
  constexpr double kZSmallest = 3.09, kZLargest = 3.63;
  for (const double err : {0.01, 0.04, 0.1}) {
    const std::string where = "relative error " + std::to_string(err);
    FlowCurve ramp = thickening_ramp();
    for (FlowPoint& p : ramp.points) p.shear_rate_err = err * p.shear_rate;
    const double last = ramp.points.back().shear_rate;
    // The new point's rate, known to the same relative error.
    const auto point_below_last = [&](double fall) {
      const double rate = last * std::exp(-fall);
      return simulated(1e5, rate, err * rate);
    };
    const double small = 0.5 * kZSmallest * std::sqrt(2.0) * err;
    FlowCurve within = ramp;
    within.points.push_back(point_below_last(small));
    EXPECT_NE(analyse_curve(within, AnalysisSettings{}).dst_evidence, DstEvidence::RateFalls)
        << where;
    const double large = 2.0 * kZLargest * std::sqrt(2.0) * err;
    FlowCurve beyond = ramp;
    beyond.points.push_back(point_below_last(large));
    EXPECT_EQ(analyse_curve(beyond, AnalysisSettings{}).dst_evidence, DstEvidence::RateFalls)
        << where;
  }
}

// Two points have no onset, yet a rate that falls as the stress rises tenfold,
// by more than the threshold of one step (z = 3.09, combined noise sqrt(2) 4%),
// is DST; a rise, or a fall within the noise, leaves the curve unresolved.
TEST(RateFalls, ATwoPointRampWhoseRateFallsIsDst) {
  constexpr double kErr = 0.04, kZOneStep = 3.09;
  const auto two_points = [&](double fall) {
    FlowCurve c;
    c.source = "two.csv";
    c.points.push_back(simulated(1e4, 5.32, kErr * 5.32));
    const double rate = 5.32 * std::exp(-fall);
    c.points.push_back(simulated(1e5, rate, kErr * rate));
    return analyse_curve(c, AnalysisSettings{});
  };
  const double threshold = kZOneStep * std::sqrt(2.0) * kErr;
  const CurveResult falls = two_points(2.0 * threshold);
  EXPECT_EQ(falls.regime, Regime::Dst);
  EXPECT_EQ(falls.dst_evidence, DstEvidence::RateFalls);
  EXPECT_EQ(falls.fall_stress, 1e5);
  EXPECT_EQ(two_points(0.5 * threshold).regime, Regime::Unresolved);
  EXPECT_EQ(two_points(-1.0).regime, Regime::Unresolved);  // the rate rises e-fold
}

// False calls on noisy curves whose rate never falls, with sigma estimated from
// the scatter as for rheometer data (49 points): the nearly flat n = 6 (the
// rate grows 3.3% a step against 3% noise) is the hardest case. At most 1 in
// 1000 curves by the Bonferroni bound; 1000 replicates expect at most 1, and 5
// or more would happen with probability 0.004 if the bound held.
TEST(RateFalls, NoisyCurvesWhoseRateNeverFallsAreAlmostNeverCalledDst) {
  constexpr int kReplicates = 1000;
  for (const double n : {1.0, 6.0}) {
    int falls = 0;
    for (int seed = 1; seed <= kReplicates; ++seed) {
      CurveModel model;
      model.n = n;
      model.noise = 0.03;
      model.seed = static_cast<unsigned>(seed);
      falls +=
          analyse_curve(model.curve(), AnalysisSettings{}).dst_evidence == DstEvidence::RateFalls
              ? 1
              : 0;
    }
    EXPECT_LE(falls, 4) << "n " << n << ": " << falls << " of " << kReplicates;
  }
}

}  // namespace
}  // namespace dilatant::analysis::rate_falls_test
