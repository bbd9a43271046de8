#pragma once
// Amontons–Coulomb friction with a constant coefficient mu0: the paper's
// "no hydrodynamics" control run.
#include "friction/defaults.hpp"
#include "friction/sommerfeld.hpp"
#include "friction/tangential_problem.hpp"

namespace dilatant {

struct CoulombLaw {
  double mu0 = friction_defaults::kMu0;
  double eta_f = 0.0;  // only to report the Sommerfeld number; friction ignores it

  double mu(double /*sommerfeld*/) const { return mu0; }

  // Stick if the impulse that stops sliding, |u_t_free| / w_t, lies inside the
  // cone mu0 * p_n; otherwise slide with |P_t| = mu0 * p_n.
  TangentialSolution solve(const TangentialProblem& p) const {
    TangentialSolution out;
    if (p.normal_impulse <= 0.0) {
      out.sliding_speed = p.free_slip;
      return out;
    }
    const double sticking_impulse = p.free_slip / p.compliance;
    const double cone = mu0 * p.normal_impulse;
    if (sticking_impulse <= cone) {
      out.impulse = sticking_impulse;
      out.regime = Regime::Stick;
      return out;
    }
    out.impulse = cone;
    out.sliding_speed = p.free_slip - p.compliance * cone;
    out.sommerfeld = sommerfeld_number(
        sommerfeld_per_speed(eta_f, p.reduced_radius, p.dt, p.normal_impulse), out.sliding_speed);
    out.regime = Regime::BoundaryLubricated;
    return out;
  }
};

}  // namespace dilatant
