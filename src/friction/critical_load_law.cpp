#include "friction/critical_load_law.hpp"

#include "friction/sommerfeld.hpp"

namespace dilatant {

bool CriticalLoadLaw::frictional(double normal_impulse, double dt, FrictionBranch branch) const {
  switch (branch) {
    case FrictionBranch::Boundary:
      return true;
    case FrictionBranch::Frictionless:
      return false;
    case FrictionBranch::Any:
    case FrictionBranch::Hydrodynamic:
    case FrictionBranch::KeepHydrodynamic:
      break;
  }
  return normal_impulse >= critical_load * dt;
}

TangentialSolution CriticalLoadLaw::solve(const TangentialProblem& p) const {
  TangentialSolution out;
  // Rule 1: no load, no friction.
  if (p.normal_impulse <= 0.0) {
    out.sliding_speed = p.free_slip;
    return out;
  }
  const auto report_sommerfeld = [&] {
    out.sommerfeld = sommerfeld_number(
        sommerfeld_per_speed(eta_f, p.reduced_radius, p.dt, p.normal_impulse), out.sliding_speed);
  };
  // Rule 2: below the critical load the contact slides without friction.
  if (!frictional(p.normal_impulse, p.dt, p.branch)) {
    out.sliding_speed = p.free_slip;
    out.regime = Regime::Frictionless;
    report_sommerfeld();
    return out;
  }
  // Rule 3: Coulomb with mu0 (as CoulombLaw::solve).
  const double sticking_impulse = p.free_slip / p.compliance;
  const double cone = mu0 * p.normal_impulse;
  if (sticking_impulse <= cone) {
    out.impulse = sticking_impulse;
    out.regime = Regime::Stick;
    return out;
  }
  out.impulse = cone;
  out.sliding_speed = p.free_slip - p.compliance * cone;
  out.regime = Regime::BoundaryLubricated;
  report_sommerfeld();
  return out;
}

}  // namespace dilatant
