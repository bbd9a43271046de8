#include "friction/stribeck_law.hpp"

#include <cmath>
#include <numbers>

namespace dilatant {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kLubricationScale = 5.0 / (6.0 * std::numbers::pi);  // mu_HD = 2 pi s ln(a/s)
}  // namespace

double StribeckLaw::hydrodynamic_mu(double s) { return kTwoPi * s * std::log(kLubricationScale / s); }

double StribeckLaw::mu(double s) const {
  if (s < s_c) return mu0;
  return hydrodynamic_mu(s < s_lim ? s : s_lim);
}

TangentialSolution StribeckLaw::solve(const TangentialProblem& p) const {
  TangentialSolution out;
  if (p.normal_impulse <= 0.0) {
    out.sliding_speed = p.free_slip;
    return out;
  }
  // Branch 1: stick inside the mu0 cone.
  const double cone = mu0 * p.normal_impulse;
  const double w = p.compliance;
  if (p.free_slip <= w * cone) {
    out.impulse = p.free_slip / w;
    out.regime = Regime::Stick;
    return out;
  }
  // Branch 2: boundary-lubricated sliding, if it is self-consistent (s < s_c).
  const double k = eta_f * p.reduced_radius * p.dt / p.normal_impulse;  // s = k * v_s
  const double v_bl = p.free_slip - w * cone;
  if (k * v_bl < s_c) {
    out.impulse = cone;
    out.sliding_speed = v_bl;
    out.sommerfeld = k * v_bl;
    out.regime = Regime::BoundaryLubricated;
    return out;
  }
  // Branch 3: hydrodynamic sliding; root of f(v) = v + w p_n mu(k v) - free_slip.
  const double wp = w * p.normal_impulse;
  const double s_cap = s_lim;
  auto f = [&](double v) { return v + wp * mu(k * v) - p.free_slip; };
  double lo = s_c / k;      // f(lo) <= 0 when mu_HD(s_c) <= mu0
  double hi = p.free_slip;  // f(hi) >= 0
  if (f(lo) >= 0.0) {
    // mu_HD(s_c) > mu0 (a tiny mu0): neither branch is consistent, the solution
    // sits on the jump itself, sliding at s = s_c with a friction between mu0
    // and mu_HD(s_c) -- the set-valued law's only answer.
    out.sliding_speed = lo;
    out.sommerfeld = s_c;
    out.impulse = (p.free_slip - lo) / w;
    out.regime = Regime::Hydrodynamic;
    return out;
  }
  double v = v_bl;          // BL speed is an upper estimate: mu_HD < mu0 near s_c
  if (v < lo || v > hi) v = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double fv = f(v);
    if (fv > 0.0) hi = v; else lo = v;
    const double s = k * v;
    const double dmu = s < s_cap ? kTwoPi * (std::log(kLubricationScale / s) - 1.0) : 0.0;
    const double dfdv = 1.0 + wp * dmu * k;
    double next = v - fv / dfdv;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    if (std::abs(next - v) <= 1e-15 * v || hi - lo <= 1e-15 * hi) { v = next; break; }
    v = next;
  }
  out.sliding_speed = v;
  out.sommerfeld = k * v;
  out.impulse = (p.free_slip - v) / w;
  out.regime = Regime::Hydrodynamic;
  return out;
}

}  // namespace dilatant
