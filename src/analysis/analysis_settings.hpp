#pragma once
// The user-adjustable rules of the rheometer analysis, with their defaults and
// why (docs/analysis.md explains each rule in full).

namespace dilatant::analysis {

struct AnalysisSettings {
  // Thickening starts where the (median-smoothed) viscosity first exceeds
  // onset_factor x the Newtonian plateau: 10% is well above the 1-3% scatter of
  // a rheometer and still at the foot of the thickening branch.
  double onset_factor = 1.1;
  // Beyond this exponent a curve counts as DST: at n = 10 the shear rate grows
  // by only 10^(1/11) = 1.23 per decade of stress, which a stress ramp cannot
  // tell from a rate plateau (the signature of DST).
  double dst_n_cap = 10.0;
  // The automatic thickening window starts with this many points at the top of
  // the ramp and grows down towards the onset while the curve stays straight.
  int min_window_points = 4;
  // A CST curve is Bagnold (n = 1) only when its interval of n lies inside
  // (1/f, f): an interval of 0.7-11.8 contains 1 but cannot tell Bagnold from
  // much steeper thickening. f = 3 puts the bounds halfway, in b = 1/(n+1),
  // between Bagnold (b = 0.5) and the Newtonian (1) and plateau (0) limits.
  double bagnold_resolution = 3.0;
  // Of the confidence intervals n_low..n_high.
  double confidence = 0.95;
  // No point is trusted better than this relative precision of the shear rate
  // (about 3 significant digits in exports); it also keeps noiseless synthetic
  // data from giving zero-width intervals.
  double noise_floor = 0.005;
};

}  // namespace dilatant::analysis
