#pragma once
// The critical-load friction law (Seto, Mari, Morris & Denn, PRL 111, 218301
// (2013); Mari, Seto, Morris & Denn, J. Rheol. 58, 1693 (2014)): a contact is
// frictionless while its normal force is below the critical load F*, and
// Coulomb-frictional with mu0 from F* on:
//
//     mu(N) = 0      N <  F*     frictionless        (Regime::Frictionless)
//     mu(N) = mu0    N >= F*     Coulomb             (Regime::Stick, BoundaryLubricated)
//
// N = p_n / dt is the contact's normal force over the step, as for the
// Stribeck law (friction/sommerfeld.hpp); a squeeze film's impulse is not part
// of it (the critical load is what the touching surfaces carry, the contact
// force of the papers above, not the fluid's).
//
// Units. F* is a material constant: a stress sweep must cross it. In the shear
// cell the applied stress is the unit of the code, so the law takes F* in code
// units, converted once from friction.critical_load, which is given in the
// paper's force unit eta_f^2/rho_p (Config::critical_load(); docs/model.md
// "Friction", the critical-load law).
//
// The local problem. The Delassus operator of a contact is diagonal in the
// contact frame (solver/contact_solver.hpp), so p_n is solved first and alone,
// and fixes N; given N the tangential answer is CoulombLaw's with mu(N):
//   1. p_n <= 0: open, no friction.
//   2. N < F* (p_n < F* dt): no friction, P_t = 0, v_s = |u_t_free|.
//   3. N >= F*: stick if |u_t_free| / w_t <= mu0 p_n, else slide with
//      |P_t| = mu0 p_n, v_s = |u_t_free| - w_t mu0 p_n.
//
// Uniqueness at the threshold. As a set-valued law (the graph of mu(N) closed
// at its jump) a contact carrying exactly N = F* may take any friction impulse
// in [0, min(mu0 p_n, |u_t_free| / w_t)]. We take the frictional end (the law
// is closed on the frictional side, N >= F*), so solve() is a function of
// (|u_t_free|, p_n) and the local problem has exactly one answer for every
// load. It is discontinuous in p_n at F* dt: the friction impulse jumps by
// min(mu0 F* dt, |u_t_free| / w_t). A contact loaded near F* can therefore flip
// status from one pass to the next as its neighbours move (a frictional
// contact turns its spheres and so loads or unloads its neighbours, which load
// it back), and the whole packing may have a frictional and a frictionless
// answer both consistent: the global problem is not unique, and the
// iteration picks one, as at the Stribeck law's jump at s_c.
//
// The threshold as a status. The solver's frozen branches
// (solver/contact_solver.hpp) hold it: after freeze_branches_after passes a
// contact keeps its status whatever its load, FrictionBranch::Boundary (the mu0
// cone) if it was stuck or sliding with mu0, FrictionBranch::Frictionless if it
// was below F*. Any other branch (Any; KeepHydrodynamic and Hydrodynamic,
// which belong to the Stribeck law's speed dependence) takes rules 1-3.
#include "friction/defaults.hpp"
#include "friction/tangential_problem.hpp"

namespace dilatant {

struct CriticalLoadLaw {
  double mu0 = friction_defaults::kMu0;
  double critical_load = 0.0;  // F*, a force in the simulation's units
  double eta_f = 0.0;          // only to report the Sommerfeld number; friction ignores it

  // The friction coefficient of a contact carrying the normal force N.
  double mu_at_load(double normal_force) const { return normal_force >= critical_load ? mu0 : 0.0; }
  // Whether a contact carrying p_n over dt is frictional: rule 2 or 3, or the
  // status a frozen branch imposes. p_n >= F* dt, not p_n / dt >= F*: one
  // rounding fewer, and exactly the test at N = F* when F* dt is exact.
  bool frictional(double normal_impulse, double dt, FrictionBranch branch) const;
  TangentialSolution solve(const TangentialProblem& p) const;
};

}  // namespace dilatant
