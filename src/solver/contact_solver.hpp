#pragma once
// Contact Dynamics solver: nonlinear Gauss–Seidel over contacts (Moreau 1994,
// Jean 1999; Brendel, Unger & Wolf 2004 for granular flows).
//
// The local problem of one contact, others frozen
// ------------------------------------------------
// Body i touches partner j at x_i - r_i n (n points from j to i). The relative
// velocity of i's surface with respect to j's at the contact point is
//
//     u = v_i - v_j - (r_i w_i + r_j w_j) x n .
//
// An impulse P on i (and -P on j) changes it by u -> u + W P with the Delassus
// operator of two spheres, I_k = 2/5 m_k r_k^2:
//
//     W = (1/m_i + 1/m_j) nn^T + (1/m_i + 1/m_j + r_i^2/I_i + r_j^2/I_j) (1 - nn^T)
//       =        w_n      nn^T +                 w_t                    (1 - nn^T)
//
// (because (n x P) x n = P_t). W is diagonal in the contact frame, so the normal
// and tangential parts decouple and each is solved exactly in closed form:
//
//   normal (Signorini, zero restitution, gap g at the start of the step): the
//   surfaces may close the gap but not overlap at the end of the step,
//       g + dt u_n >= 0,  p_n >= 0,  p_n (g + dt u_n) = 0
//   =>  p_n = max(0, -(u_n_free + g/dt) / w_n),
//   where u_n_free is u_n without this contact's impulse;
//
//   tangential: the friction law, given u_t_free, w_t, p_n (friction/).
//
// Passes
// ------
// A pass visits the contacts one after another (a Gauss–Seidel sweep, the
// literature's word, which the settings and outputs keep: solver.max_sweeps,
// sweep_equivalents; the code says "pass" so that "sweep" names only a
// parameter sweep, src/sweep/). Velocities always hold v_free + M^-1 H P for
// the current impulses P, so visiting a contact costs one gather of two
// bodies, the local solve, and one scatter of the impulse change.
//
// When to stop (SolverSettings::convergence; docs/model.md "Convergence
// criterion"). Under Residual, the passes repeat until the contact problem's
// residual (solver/contact_residual.hpp: every contact's distance from the
// exact answer of its local problem, in units of the reference impulse P_ref
// the driver sets from the applied load) is at most `tolerance` for every
// contact. Evaluating it costs about a pass, so it is evaluated only on a full
// pass in which no contact's impulse changed by more than kResidualTrigger x
// tolerance x P_ref (the trigger). A pass's change is the residual each
// contact had when visited, but contacts visited later can undo it: a
// dumped step of the default cell crept along such a mode for 700 passes,
// changing a contact by more than 0.01 P_ref every pass at a residual of
// 0.0084; hence the factor 10 rather than 1. A failed evaluation defers the
// next by 1, 2, 4, 8, then 16 passes, so that a solve crawling just above
// the tolerance pays at most one evaluation per 16 passes. The evaluations
// count as work (one visit per contact).
//
// Under Change, the passes repeat until the relative change of the impulse
// vector,
//
//     residual = sqrt( max(0, sum_c |P_c^new - P_c^old|^2 - noise^2) / sum_c |P_c^new|^2 ),
//
// drops to `tolerance` (0 when no contact carries load and nothing changed).
// A self-stress locked into a jammed packing inflates sum |P|^2 and can meet
// this far from the answer (docs/model.md "Overlap push-out"), hence Residual.
// Under either, after `max_iterations` passes the step is reported unconverged.
// noise^2 = sum_c (16 eps |v|_c / w_n)^2, |v|_c = |v_i| + r_i |w_i| + |v_j| + r_j |w_j|,
// is the round-off of recomputing the impulses from velocities of that size:
// changes below it are not progress. Without it a contact whose load is itself
// round-off (two spheres moving together, gap -1e-16 pushed out at 1e-13/dt)
// never meets the relative test and runs all max_iterations passes
// (tests/validation/head_on_collision_test.cpp); the residual discounts it
// contact by contact.
// Warm start: impulses of the previous step are applied before the first pass.
//
// The stages of one solve (solve_contacts), each handed the one
// ContactProblem (solver/contact_problem.hpp), not a list of arguments:
//
//   boundary block   the boundary's own degrees of freedom, given the
//                    warm-started impulses (boundary/boundary.hpp)
//   pass             even slabs side by side, then odd ones; in each slab
//                    the contacts between dynamic bodies under the law, then
//                    those touching a driven body under the boundary's law
//                    (solver/slab_partition.hpp)
//   change           of the pass, from the slabs' sums added in slab order
//   boundary block   by one thread, while the others start the next even slabs
//   [residual]       under Residual, when the trigger holds on a full pass:
//                    all slabs side by side, after the boundary block
//   [acceleration]   the conjugate-gradient step, then the boundary block again
//   ... until the test holds on a full pass, or max_iterations passes.
//
// Frozen branches. With the Stribeck law the friction jumps from mu0 to
// mu_HD(s_c) ~ 0.003 at s = s_c. A contact near the jump flips branch from one
// pass to the next as its neighbours move, changing its impulse by ~mu0 p_n
// each time, and the iteration cycles instead of converging (a prototype hit
// its cap in half the steps). After `freeze_branches_after` passes each contact
// therefore keeps the branch it took last (BL: stick or slide with mu0; HD:
// slide on mu_HD(s) for any s), which is a continuous problem that Gauss–Seidel
// solves. Only contacts within the jump's reach can end up "inconsistent" (a BL
// contact at s slightly above s_c or vice versa); their number is what the
// branch rule could not decide anyway.
//
// Open contacts. The detector's margin covers the fastest approach in the cell,
// so most contacts it finds stay open (on the paper's cell at lambda 100, about
// 4 in 5): their local answer is no impulse at all, and visiting them changes
// nothing. With `skip_open_contacts`, a full pass lists the contacts that end
// it with an impulse; the next passes visit only those, until every
// kFullPassEvery-th pass, or the pass after one that met the tolerance, is
// full again. The solve ends only on a full pass that meets the tolerance, so
// the criterion, and the answer it accepts, are those of plain passes; a
// contact that closes in between is picked up by the next full pass.
//
// A boundary (boundary/boundary.hpp) is one more block of the Gauss–Seidel
// iteration: its driven bodies (world/bodies.hpp) have infinite mass in the
// contact problems, and after each pass it solves its own degrees of freedom
// exactly given the contact impulses. Contact passes never wait on it.
#include <vector>

#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "solver/contact_problem.hpp"
#include "solver/contact_residual.hpp"
#include "world/bodies.hpp"

namespace dilatant {

struct SolveReport {
  int iterations = 0;  // passes, full and partial
  // The solve's work: local solves over all passes, plus one per contact for
  // every residual the stopping test evaluated (/contacts: sweep-equivalents).
  double contact_visits = 0.0;
  // The stopping test's value when the solve ended: the relative change of
  // the last pass (Change), or the last residual evaluated (Residual).
  double residual = 0.0;
  bool converged = true;
  // Under Residual, the contact residual of the final impulses when the solve
  // evaluated it there (always when it converged): the stepper reports it
  // rather than computing it again.
  bool final_residual_known = false;
  ContactResidual final_residual;
};

// Sums accumulated over one pass, from which the stopping test follows.
struct PassChange {
  double change_squared = 0.0;      // sum |dP|^2
  double impulse_squared = 0.0;     // sum |P|^2
  double visits = 0.0;              // contacts visited
  double max_change_squared = 0.0;  // max |dP|^2: the residual's trigger
  double loaded = 0.0;              // contacts carrying an impulse after their visit
};

// With skip_open_contacts, every kFullPassEvery-th pass visits all contacts.
inline constexpr int kFullPassEvery = 8;
// Under Residual (header, "When to stop"): the largest change of a pass that
// lets the residual be evaluated, in units of tolerance x P_ref, and the
// longest deferral after failed evaluations, in passes.
inline constexpr double kResidualTrigger = 10.0;
inline constexpr int kLongestDeferral = 16;

// Over-relaxation holds for the first half of max_iterations; a solve that
// has not converged by then goes on as plain Gauss–Seidel. With omega 1.3 a
// sliding contact on the wall (mu 1) and its neighbours can fall into a
// period-2 cycle of over-relaxed passes, at a residual of 2.9 P_ref that no
// number of passes lowers; plain passes solve the same dumped step in 24
// (docs/model.md "Over-relaxation"). A solve that converges within half its
// passes is unchanged (fading omega earlier, halving its excess every 100
// passes, cost 8% more work to 1e-2 on the paper cell's dumped steps).
double relaxation_at_pass(const SolverSettings& settings, int pass);

// Adds M^-1 H P of the contacts' current impulses to the body velocities.
void apply_impulses(const std::vector<Contact>& contacts, Bodies& bodies);

// One plain Gauss–Seidel pass over all contacts in order.
PassChange gauss_seidel_pass(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                             double dt);

// All contacts in one slab under one law, no boundary.
SolveReport solve_contacts(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                           double dt, const SolverSettings& settings);

// The impulses do not depend on problem.settings.threads.
SolveReport solve_contacts(const ContactProblem& problem);

}  // namespace dilatant
