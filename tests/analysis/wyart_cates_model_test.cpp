// The Wyart–Cates model's flow states against computations that do not share
// its code: the DST boundary (the lowest phi whose stress-controlled curve
// turns back) and the S's stresses from a fine scan of gamma_dot(sigma) =
// sigma/eta(sigma) itself, and from the closed form of the threshold; the
// shear-jamming line against phi_J(sigma) = phi.
#include "analysis/wyart_cates_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dilatant::analysis::wyart_cates_model_test {
namespace {

// Singh et al. (2018)'s mu = 1 fractions, sigma* 1, A 1, alpha 2, beta 1.
const WyartCatesParameters kModel{0.64, 0.56, 1.0, 1.0, 2.0, 1.0};

// Whether gamma_dot = sigma/eta decreases anywhere on a fine stress grid (1e-4 to
// 1e4 sigma*, 40000 nodes) before the suspension jams: by the viscosity alone.
bool turns_back_by_scan(const WyartCatesParameters& p, double phi) {
  double last = 0.0;
  for (int k = 0; k <= 40000; ++k) {
    const double sigma = p.sigma_star * std::pow(10.0, -4.0 + 8.0 * k / 40000.0);
    const double eta = wyart_cates_viscosity(p, phi, sigma);
    if (!std::isfinite(eta)) return k > 0;  // jams: the branch ends at a zero rate
    const double rate = sigma / eta;
    if (rate < last) return true;
    last = rate;
  }
  return false;
}

double onset_by_scan(const WyartCatesParameters& p) {
  double lo = 0.3, hi = p.phi_m;
  for (int k = 0; k < 40; ++k) {
    const double m = 0.5 * (lo + hi);
    (turns_back_by_scan(p, m) ? hi : lo) = m;
  }
  return 0.5 * (lo + hi);
}

// The closed form of the threshold. Eq. (*) of the header equals 1 at
//   phi_1(x) = phi_J^2 / (phi_J + alpha beta Delta x e^-x),  phi_J = phi_0 - Delta e^-x,
// (a linear equation in phi), and (*) grows with phi, so the curve turns back
// at x where phi > phi_1(x): phi_DST = min over x of phi_1(x).
double threshold_phi(const WyartCatesParameters& p, double x) {
  const double delta = p.phi_0 - p.phi_m, e = std::exp(-x);
  const double phi_j = p.phi_0 - delta * e;
  return phi_j * phi_j / (phi_j + p.alpha * p.beta * delta * x * e);
}

double onset_by_closed_form(const WyartCatesParameters& p) {
  double best = 1.0;
  for (int k = 0; k <= 200000; ++k)
    best = std::min(best, threshold_phi(p, 1e-6 * std::pow(1e8, k / 200000.0)));
  return best;
}

TEST(WyartCatesModel, ViscosityFollowsTheJammingFractionFromPhi0ToPhiM) {
  // Far below sigma*: frictionless, eta = A (1 - phi/phi_0)^-2; far above: phi_m.
  EXPECT_NEAR(wyart_cates_viscosity(kModel, 0.5, 1e-4), std::pow(1.0 - 0.5 / 0.64, -2.0), 1e-9);
  EXPECT_NEAR(wyart_cates_viscosity(kModel, 0.5, 1e6), std::pow(1.0 - 0.5 / 0.56, -2.0),
              1e-5 * 87.1);  // f = 1 - 1e-6 there
  EXPECT_NEAR(frictional_fraction(kModel, 1.0), std::exp(-1.0), 1e-15);
  EXPECT_NEAR(jamming_fraction(kModel, 1.0), 0.64 - 0.08 * std::exp(-1.0), 1e-15);
  EXPECT_TRUE(std::isinf(wyart_cates_viscosity(kModel, 0.60, 1e3)));
}

TEST(WyartCatesModel, ThickeningSlopeIsTheDerivativeOfLnEta) {
  for (const double phi : {0.45, 0.54, 0.58})
    for (const double sigma : {0.05, 0.3, 1.0, 4.0}) {
      if (!std::isfinite(wyart_cates_viscosity(kModel, phi, sigma * 1.01))) continue;
      const double h = 1e-5;
      const double numeric = (std::log(wyart_cates_viscosity(kModel, phi, sigma * std::exp(h))) -
                              std::log(wyart_cates_viscosity(kModel, phi, sigma * std::exp(-h)))) /
                             (2 * h);
      EXPECT_NEAR(thickening_slope(kModel, phi, sigma), numeric, 1e-6 * (1 + numeric))
          << phi << " " << sigma;
    }
}

TEST(WyartCatesModel, DstOnsetMatchesTheScanOfTheFlowCurveAndTheClosedForm) {
  for (const auto& p : {kModel, WyartCatesParameters{0.64, 0.58, 1.0, 1.0, 2.0, 1.0},
                        WyartCatesParameters{0.655, 0.575, 3.0, 0.2, 2.0, 1.5}}) {
    const DstOnset onset = dst_onset(p);
    EXPECT_NEAR(onset.phi, onset_by_closed_form(p), 1e-8) << p.phi_m;
    EXPECT_NEAR(onset.phi, onset_by_scan(p), 2e-5) << p.phi_m;
    EXPECT_LT(onset.phi, p.phi_m);  // alpha beta > 1
    // At the onset the slope just reaches 1 at the reported stress.
    EXPECT_NEAR(thickening_slope(p, onset.phi, onset.stress), 1.0, 1e-6);
    EXPECT_EQ(flow_curve_regime(p, onset.phi - 1e-4), "cst");
    EXPECT_EQ(flow_curve_regime(p, onset.phi + 1e-4), "dst");
  }
  // For these parameters phi_DST = 0.54637 (the closed form above, printed once),
  // 0.0136 below phi_m.
  EXPECT_NEAR(dst_onset(kModel).phi, 0.54637, 1e-5);
}

TEST(WyartCatesModel, OnsetFractionDoesNotDependOnSigmaStarOrA) {
  WyartCatesParameters p = kModel;
  p.sigma_star = 40.0;
  p.A = 7.0;
  EXPECT_NEAR(dst_onset(p).phi, dst_onset(kModel).phi, 1e-12);
  EXPECT_NEAR(dst_onset(p).stress / 40.0, dst_onset(kModel).stress, 1e-9);
}

TEST(WyartCatesModel, TurningRangeIsWhereTheRateFallsWithStress) {
  const double phi = 0.55;
  const TurningRange r = turning_range(kModel, phi);
  ASSERT_TRUE(r.exists());
  EXPECT_LT(r.low, r.high);
  // Inside the range the rate falls, just outside it grows (finite differences).
  const auto rate = [&](double s) { return s / wyart_cates_viscosity(kModel, phi, s); };
  const auto falls = [&](double s) { return rate(s * 1.0001) < rate(s); };
  EXPECT_TRUE(falls(std::sqrt(r.low * r.high)));
  EXPECT_TRUE(falls(r.low * 1.001));
  EXPECT_FALSE(falls(r.low * 0.999));
  EXPECT_TRUE(falls(r.high * 0.999));
  EXPECT_FALSE(falls(r.high * 1.001));
  EXPECT_FALSE(turning_range(kModel, dst_onset(kModel).phi - 1e-3).exists());
}

TEST(WyartCatesModel, ShearJammingLineIsWherePhiJReachesPhi) {
  for (const double phi : {0.565, 0.60, 0.635}) {
    const double s = shear_jamming_stress(kModel, phi);
    EXPECT_NEAR(jamming_fraction(kModel, s), phi, 1e-12);
    EXPECT_TRUE(std::isfinite(wyart_cates_viscosity(kModel, phi, s * 0.999)));
    EXPECT_TRUE(std::isinf(wyart_cates_viscosity(kModel, phi, s * 1.001)));
    EXPECT_EQ(flow_curve_regime(kModel, phi), "shear_jamming");
    // The S ends in jamming: its upper stress is the shear-jamming stress.
    EXPECT_EQ(turning_range(kModel, phi).high, s);
    EXPECT_EQ(flow_state(kModel, phi, s * 1.01), FlowState::Jammed);
  }
  EXPECT_TRUE(std::isinf(shear_jamming_stress(kModel, 0.55)));  // below phi_m: never jams
  EXPECT_EQ(shear_jamming_stress(kModel, 0.65), 0.0);           // above phi_0: never flows
  EXPECT_EQ(flow_curve_regime(kModel, 0.65), "no_flow");
}

TEST(WyartCatesModel, WithoutFrictionalJammingBelowPhi0NothingThickens) {
  const WyartCatesParameters p{0.60, 0.62, 1.0, 1.0, 2.0, 1.0};
  EXPECT_TRUE(std::isnan(dst_onset(p).phi));
  EXPECT_FALSE(turning_range(p, 0.58).exists());
  EXPECT_EQ(flow_curve_regime(p, 0.58), "cst");
}

}  // namespace
}  // namespace dilatant::analysis::wyart_cates_model_test
