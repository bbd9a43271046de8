#pragma once
// The simplified Stribeck curve of the paper (Eq. 1) with our cap beyond s_lim:
//
//     mu(s) = mu0                        s <  s_c            boundary lubrication (BL)
//     mu(s) = 2 pi s ln(5 / (6 pi s))    s_c <= s < s_lim    hydrodynamic (HD)
//     mu(s) = mu(s_lim)                  s >= s_lim          outside lubrication theory
//
// or, with `viscous_beyond_s_lim` (friction.beyond_s_lim = "viscous"), the
// viscous continuation mu(s) = mu(s_lim) s / s_lim: since s = eta_f R_p v_s / N,
// the friction force is then F_t = mu(s_lim) eta_f R_p v_s / s_lim, linear in
// the sliding speed and independent of the load -- a lubricated contact that
// slides fast carries a viscous shear force, not a dry one. Continuous at s_lim,
// and increasing, so the HD root below stays unique.
//
// Because mu depends on the sliding speed, one contact's local problem can have
// several consistent answers. We resolve it deterministically (docs/model.md "Friction"):
//   1. stick, if the sticking impulse |u_t_free|/w_t lies in the mu0 cone;
//   2. else slide with mu0, if the resulting speed gives s < s_c;
//   3. else slide on the HD branch: find v_s > 0 with
//          f(v_s) = v_s + w_t p_n mu(k v_s) - |u_t_free| = 0,   k = eta_f R_p dt / p_n,
//      (s = k v_s because N = p_n/dt). f(v_c) <= 0 at v_c = s_c/k (step 2 failed
//      and mu_HD(s_c) < mu0) and f(|u_t_free|) >= 0, so a root lies in between;
//      mu is increasing on the HD branch up to s = 5/(6 pi e) ~ 0.0976, so f is
//      monotone there and the root is unique (up to s_lim = 0.1, slightly past
//      the maximum, where mu falls by < 0.1%). We find it by Newton's method
//      safeguarded by bisection. If mu0 < mu_HD(s_c) (mu0 below ~0.003 at the
//      default s_c), f(v_c) > 0 and the contact slides exactly at s = s_c with
//      the friction in between that the jump allows.
//  A solver may impose the branch (TangentialProblem::branch): Boundary skips the
//  s < s_c test of step 2, Hydrodynamic solves step 3 on the whole HD curve
//  (v_s from 0). See solver/contact_solver.hpp for why.
//
//  Continuity of the HD branch in time (KeepHydrodynamic). Rule 1 alone lets a
//  contact that slides on the HD branch stick at once whenever mu0 N dt could
//  stop it within the step, i.e. whenever v_s < mu0 N w_t dt, although in the
//  continuous dynamics it slides on with the weak HD friction until its speed
//  falls to v_c = s_c N/(eta_f R_p). With dt above the BL stopping time
//  s_c/(mu0 eta_f R_p w_t) (~2e-4 lambda in the shear cell) this captures HD
//  contacts in proportion to dt: P_BL was first order in dt (docs/shear-cell.md).
//  So a contact that slid on the HD branch in the previous step stays on it while
//  an HD answer with s >= s_c exists; only when its speed would fall below v_c
//  does rule 1-3 decide. Both rules have the same dt -> 0 limit.
//  The paper's HD formula needs s_c < 5/(6 pi) for mu > 0; the config checks it.
#include "friction/defaults.hpp"
#include "friction/tangential_problem.hpp"

namespace dilatant {

struct StribeckLaw {
  double mu0 = friction_defaults::kMu0;
  double s_c = friction_defaults::kSc;
  double s_lim = friction_defaults::kSlim;
  double eta_f = 0.0;                 // fluid viscosity, in the units of the simulation
  bool viscous_beyond_s_lim = false;  // false: the cap (the paper's literal law)

  // Lubrication-theory friction (paper, Supplemental Material), no cap.
  static double hydrodynamic_mu(double s);
  double mu(double s) const;
  TangentialSolution solve(const TangentialProblem& p) const;

 private:
  double hydrodynamic_root(const TangentialProblem& p, double k, double lo) const;
};

}  // namespace dilatant
