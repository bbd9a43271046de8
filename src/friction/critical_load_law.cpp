#include "friction/critical_load_law.hpp"

#include "friction/coulomb_law.hpp"
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
  // Rule 1 (no load, no friction) and rule 3 (from the critical load on,
  // Coulomb with mu0) are CoulombLaw's.
  if (p.normal_impulse <= 0.0 || frictional(p.normal_impulse, p.dt, p.branch))
    return CoulombLaw{mu0, eta_f}.solve(p);
  // Rule 2: below the critical load the contact slides without friction.
  TangentialSolution out;
  out.sliding_speed = p.free_slip;
  out.regime = Regime::Frictionless;
  out.sommerfeld = sommerfeld_number(
      sommerfeld_per_speed(eta_f, p.reduced_radius, p.dt, p.normal_impulse), out.sliding_speed);
  return out;
}

}  // namespace dilatant
