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
// bodies, the local solve, and one scatter of the impulse change. Passes repeat
// until the relative change of the impulse vector,
//
//     residual = sqrt( max(0, sum_c |P_c^new - P_c^old|^2 - noise^2) / sum_c |P_c^new|^2 ),
//
// drops to `tolerance` (0 when no contact carries load and nothing changed),
// or `max_iterations` passes have run; then the step is reported unconverged.
// noise^2 = sum_c (16 eps |v|_c / w_n)^2, |v|_c = |v_i| + r_i |w_i| + |v_j| + r_j |w_j|,
// is the round-off of recomputing the impulses from velocities of that size:
// changes below it are not progress. Without it a contact whose load is itself
// round-off (two spheres moving together, gap -1e-16 pushed out at 1e-13/dt)
// never meets the relative test and runs all max_iterations passes
// (tests/validation/head_on_collision_test.cpp).
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
//   residual         of the pass, from the slabs' sums added in slab order
//   boundary block   by one thread, while the others start the next even slabs
//   [acceleration]   the conjugate-gradient step, then the boundary block again
//   ... until a full pass meets the tolerance, or max_iterations passes.
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
#include "world/bodies.hpp"

namespace dilatant {

struct SolveReport {
  int iterations = 0;           // passes, full and partial
  double contact_visits = 0.0;  // local solves over all passes (/contacts: sweep-equivalents)
  double residual = 0.0;
  bool converged = true;
};

// Sums accumulated over one pass, from which the residual follows.
struct PassChange {
  double change_squared = 0.0;   // sum |dP|^2
  double impulse_squared = 0.0;  // sum |P|^2
  double visits = 0.0;           // contacts visited
};

// With skip_open_contacts, every kFullPassEvery-th pass visits all contacts.
inline constexpr int kFullPassEvery = 8;

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
