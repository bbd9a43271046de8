#include "friction/stribeck_law.hpp"

#include <cmath>
#include <numbers>

#include "friction/sommerfeld.hpp"

namespace dilatant {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kLubricationScale = 5.0 / (6.0 * std::numbers::pi);  // mu_HD = 2 pi s ln(a/s)
}  // namespace

double StribeckLaw::hydrodynamic_mu(double s) {
  return kTwoPi * s * std::log(kLubricationScale / s);
}

double StribeckLaw::mu(double s) const {
  if (s < s_c) return mu0;
  if (s < s_lim) return hydrodynamic_mu(s);
  return viscous_beyond_s_lim ? hydrodynamic_mu(s_lim) * (s / s_lim) : hydrodynamic_mu(s_lim);
}

double StribeckLaw::hydrodynamic_root(const TangentialProblem& p, double k, double lo) const {
  // Root of f(v) = v + w p_n mu_HD(k v) - free_slip on [lo, free_slip]; f(lo) <= 0 <= f(hi).
  const double wp = p.compliance * p.normal_impulse;
  double hi = p.free_slip;
  // f and f' from one logarithm: mu = 2 pi s L, dmu/ds = 2 pi (L - 1), L = ln(a/s);
  // beyond s_lim mu is the constant cap, or its viscous continuation mu_cap s/s_lim.
  const double mu_cap = hydrodynamic_mu(s_lim);
  const double viscous_slope = viscous_beyond_s_lim ? mu_cap / s_lim : 0.0;  // d mu / ds
  const auto f_and_slope = [&](double v, double& slope) {
    const double s = sommerfeld_number(k, v);
    if (s >= s_lim) {
      slope = 1.0 + wp * k * viscous_slope;
      return v + wp * (viscous_beyond_s_lim ? viscous_slope * s : mu_cap) - p.free_slip;
    }
    const double log_term = std::log(kLubricationScale / s);
    slope = 1.0 + wp * k * kTwoPi * (log_term - 1.0);
    return v + wp * kTwoPi * s * log_term - p.free_slip;
  };
  // Start from the last sweep's answer when the solver has one (it moves little
  // between sweeps); else HD friction is weak, so the root lies near the free
  // slip and one fixed-point step from there is a close start.
  double v = p.slip_hint;
  if (!(v > lo && v < hi)) {
    const double s_free = sommerfeld_number(k, p.free_slip);
    v = p.free_slip - wp * mu(s_free);
  }
  if (!(v > lo && v < hi)) v = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    double slope = 1.0;
    const double fv = f_and_slope(v, slope);
    if (fv == 0.0) return v;  // exact root: bisecting on would only throw it away
    if (fv > 0.0)
      hi = v;
    else
      lo = v;
    double next = v - fv / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    // 1e-13 relative: far below any Gauss–Seidel tolerance, a few ulps above round-off.
    if (std::abs(next - v) <= 1e-13 * v || hi - lo <= 1e-13 * hi) return next;
    v = next;
  }
  return v;
}

TangentialSolution StribeckLaw::solve(const TangentialProblem& p) const {
  TangentialSolution out;
  if (p.normal_impulse <= 0.0) {
    out.sliding_speed = p.free_slip;
    return out;
  }
  const double w = p.compliance;
  const double cone = mu0 * p.normal_impulse;
  const double k = sommerfeld_per_speed(eta_f, p.reduced_radius, p.dt, p.normal_impulse);
  const double v_bl = p.free_slip - w * cone;
  const auto sliding = [&](double v, Regime regime) {
    out.sliding_speed = v;
    out.sommerfeld = sommerfeld_number(k, v);
    out.impulse = (p.free_slip - v) / w;
    out.regime = regime;
    return out;
  };
  const double v_c = s_c / k;
  // An HD answer with s >= s_c exists when f(v_c) < 0 (see the header).
  const bool hd_above_jump = v_c + w * p.normal_impulse * hydrodynamic_mu(s_c) < p.free_slip;
  if (p.branch == FrictionBranch::KeepHydrodynamic && hd_above_jump) {
    return sliding(hydrodynamic_root(p, k, v_c), Regime::Hydrodynamic);
  }
  if (p.branch != FrictionBranch::Hydrodynamic) {
    // Branch 1: stick inside the mu0 cone.
    if (p.free_slip <= w * cone) {
      out.impulse = p.free_slip / w;
      out.regime = Regime::Stick;
      return out;
    }
    // Branch 2: boundary-lubricated sliding, if self-consistent (s < s_c) or imposed.
    if (sommerfeld_number(k, v_bl) < s_c || p.branch == FrictionBranch::Boundary) {
      return sliding(v_bl, Regime::BoundaryLubricated);
    }
  } else if (p.free_slip <= 0.0 || k <= 0.0) {
    return sliding(p.free_slip, Regime::Hydrodynamic);
  }
  if (p.branch == FrictionBranch::Hydrodynamic) {
    return sliding(hydrodynamic_root(p, k, 0.0), Regime::Hydrodynamic);
  }
  // Branch 3: hydrodynamic sliding above s_c.
  if (!hd_above_jump) {
    // mu_HD(s_c) > mu0 (a tiny mu0): neither branch is consistent, the solution
    // sits on the jump itself, sliding at s = s_c with a friction between mu0
    // and mu_HD(s_c) -- the set-valued law's only answer.
    return sliding(v_c, Regime::Hydrodynamic);
  }
  return sliding(hydrodynamic_root(p, k, v_c), Regime::Hydrodynamic);
}

}  // namespace dilatant
