#pragma once
// One flow curve: Newtonian plateau, onset of thickening, Ostwald-de Waele
// exponent n of eta ∝ gamma_dot^n in the thickening window, and the regime.
//
// The fit is made in the variables of a stress-controlled ramp: the stress is
// imposed and known, the rate is measured with noise. In the window,
//     ln gamma_dot = a + b ln tau,   b = 1/(n+1)  (eta = tau/gamma_dot ∝ gamma_dot^n)
// is fitted by weighted least squares of ln gamma_dot on ln tau. This stays
// well posed when the curve becomes vertical in eta(gamma_dot) (b -> 0, n -> inf,
// DST) and gives an asymmetric interval for n = 1/b - 1 from the symmetric one
// for b. The rules (docs/analysis.md):
//
//  1. Noise: sigma of ln gamma_dot per point, from the simulation's error bars or,
//     for rheometer data, estimated robustly from the scatter of each point about
//     the line through its neighbours; never below AnalysisSettings::noise_floor.
//  2. Plateau: with ln eta smoothed by a running median of 3, the bottom of the
//     curve is its minimum; eta_newtonian is the median viscosity of the points
//     before the onset that lie within 3 sigma of that minimum.
//  3. Onset: the first point after the minimum where the smoothed viscosity
//     exceeds onset_factor x eta_newtonian; onset_stress is interpolated in
//     log-log, onset_rate = onset_stress / (onset_factor eta_newtonian).
//  4. Window (automatic): from the top min_window_points points of the ramp,
//     the largest window reaching down towards the onset in which a quadratic
//     term of the log-log fit stays within 2 standard errors (the power law is
//     straight within the noise). A user window replaces it.
//  5. n and its interval: b with its standard error (scaled up by sqrt(chi2/dof)
//     when the scatter exceeds sigma), Student t quantile with m - 2 degrees of
//     freedom; n_low = 1/(b + t se) - 1, n_high = 1/(b - t se) - 1, or infinity
//     when the bound is <= 0.
//  6. Regime, the first rule that applies:
//       jammed      every point of the curve is a jammed simulation (no flow at
//                   any stress of the curve);
//       dst         some point jammed while others flow (the flow stops above a
//                   critical stress);
//       newtonian   no onset in the ramp;
//       dst         b <= 0 (the rate does not increase with stress) or n > dst_n_cap;
//       dst         at or above the onset, the rate falls from one point to the
//                   next (higher stress) by more than their combined noise
//                   explains at a false-call rate of 1e-3 per curve
//                   (rate_falls: the ramp stepped across the turning point of
//                   an S-shaped flow curve);
//       unresolved  an onset but fewer than 3 fit points above it;
//       cst         otherwise.
//     A curve with fewer than 3 fit points in all is jammed, dst (a jam) or
//     unresolved by the same rules.
//  7. Bagnold check, CST curves only: eta ∝ gamma_dot (n = 1, the Bagnold
//     scaling of dense granular flow, tau ∝ gamma_dot^2) holds when the interval
//     n_low..n_high contains 1 and is narrow enough to tell it from its
//     neighbours: it lies inside (1/f, f) with f = bagnold_resolution (3), i.e.
//     b = 1/(n+1) is known to within +-0.25 of Bagnold's 0.5, halfway to the
//     Newtonian b = 1 and to a rate plateau b = 0 (bagnold_holds).
//
//  8. Contact onset, simulations only: where frac_bl rises for good above its
//     minimum (contact_onset.hpp), the onset the paper's 1/s_c scaling is about.
//
// Local slope, per fit point k: d ln eta / d ln gamma_dot = 1/b_k - 1 with
// b_k = d ln gamma_dot / d ln tau between its neighbouring fit points (centred
// difference; one-sided at the ends of the curve); +inf where the rate does not
// increase with stress (b_k <= 0). 0 on a Newtonian plateau, 1 in Bagnold
// scaling; the exponent n is its value averaged over the window.
#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "analysis/analysis_settings.hpp"
#include "analysis/flow_curve.hpp"

namespace dilatant::analysis {

enum class Regime { Newtonian, Cst, Dst, Unresolved, Jammed };
enum class DstEvidence { None, RateNotIncreasing, ExponentAboveCap, RateFalls, Jammed };

// Rule 7 on an interval of n.
bool bagnold_holds(double n_low, double n_high, const AnalysisSettings& s);

std::string_view regime_name(Regime r);  // newtonian | cst | dst | unresolved | jammed
std::string_view dst_evidence_name(
    DstEvidence e);  // "" | rate_not_increasing | n_above_cap | rate_falls | jammed

inline constexpr double kNotFound = std::numeric_limits<double>::quiet_NaN();

struct CurveResult {
  double eta_newtonian = kNotFound;
  double onset_stress = kNotFound;
  double onset_rate = kNotFound;
  double n = kNotFound;  // +inf when the rate does not increase in the window
  double n_low = kNotFound;
  double n_high = kNotFound;
  double n_sigma = kNotFound;      // standard error of n (delta method: se_b / b^2)
  double consistency = kNotFound;  // K of eta = K gamma_dot^n, in the curve's units
  double window_stress_low = kNotFound;
  double window_stress_high = kNotFound;
  std::size_t window_points = 0;
  bool window_from_user = false;
  double noise = kNotFound;  // typical relative noise of the shear rate used
  Regime regime = Regime::Newtonian;
  DstEvidence dst_evidence = DstEvidence::None;
  // Where the rate fell at or above the onset by more than rule 6's threshold
  // (whichever rule decided the regime): the stress of the point whose rate
  // fell most below the one before it, in units of their combined noise (the
  // first stress on the lower branch); else kNotFound.
  double fall_stress = kNotFound;
  // Where the contacts leave the hydrodynamic branch (contact_onset.hpp): only
  // for curves whose points carry frac_bl (simulations); else kNotFound.
  double contact_onset_stress = kNotFound;
  double contact_onset_rate = kNotFound;
  double frac_bl_min = kNotFound;
  // CST only (else empty): does the interval of n hold 1 (Bagnold scaling)?
  std::optional<bool> bagnold;
  std::vector<bool> in_window;      // per point of the curve
  std::vector<double> local_slope;  // per point: d ln eta / d ln gamma_dot; NaN if not fitted
};

// Throws InputError when the curve's user window holds fewer than 3 fit points.
CurveResult analyse_curve(const FlowCurve& curve, const AnalysisSettings& settings);

}  // namespace dilatant::analysis
