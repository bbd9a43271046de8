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
// The sweep
// ---------
// Velocities always hold v_free + M^-1 H P for the current impulses P, so
// visiting a contact costs one gather of two bodies, the local solve, and one
// scatter of the impulse change. Sweeps repeat until the relative change of the
// impulse vector,
//
//     residual = sqrt( max(0, sum_c |P_c^new - P_c^old|^2 - noise^2) / sum_c |P_c^new|^2 ),
//
// drops to `tolerance` (0 when no contact carries load and nothing changed),
// or `max_iterations` sweeps have run; then the step is reported unconverged.
// noise^2 = sum_c (16 eps |v|_c / w_n)^2, |v|_c = |v_i| + r_i |w_i| + |v_j| + r_j |w_j|,
// is the round-off of recomputing the impulses from velocities of that size:
// changes below it are not progress. Without it a contact whose load is itself
// round-off (two spheres moving together, gap -1e-16 pushed out at 1e-13/dt)
// never meets the relative test and runs all max_iterations sweeps
// (tests/validation/head_on_collision_test.cpp).
// Warm start: impulses of the previous step are applied before the first sweep.
//
// Frozen branches. With the Stribeck law the friction jumps from mu0 to
// mu_HD(s_c) ~ 0.003 at s = s_c. A contact near the jump flips branch from one
// sweep to the next as its neighbours move, changing its impulse by ~mu0 p_n
// each time, and the iteration cycles instead of converging (a prototype hit
// its cap in half the steps). After `freeze_branches_after` sweeps each contact
// therefore keeps the branch it took last (BL: stick or slide with mu0; HD:
// slide on mu_HD(s) for any s), which is a continuous problem that Gauss–Seidel
// solves. Only contacts within the jump's reach can end up "inconsistent" (a BL
// contact at s slightly above s_c or vice versa); their number is what the
// branch rule could not decide anyway.
//
// Open contacts. The detector's margin covers the fastest approach in the cell,
// so most contacts it finds stay open (on the paper's cell at lambda 100, about
// 4 in 5): their local answer is no impulse at all, and visiting them changes
// nothing. With `skip_open_contacts`, a full sweep lists the contacts that end
// it with an impulse; the next sweeps visit only those, until every
// kFullSweepEvery-th sweep, or the sweep after one that met the tolerance, is
// full again. The solve ends only on a full sweep that meets the tolerance, so
// the criterion, and the answer it accepts, are those of plain sweeps; a
// contact that closes in between is picked up by the next full sweep.
//
// A boundary (boundary/boundary.hpp), e.g. the shear cell's moving wall, is one
// more block of the Gauss–Seidel iteration: its bodies have infinite mass in the
// contact problems, and after each sweep it solves its own degrees of freedom
// exactly given the contact impulses. Contact sweeps never wait on it.
#include <cstdint>
#include <utility>
#include <vector>

#include "boundary/boundary.hpp"
#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "solver/local_problem.hpp"
#include "solver/slab_partition.hpp"
#include "world/bodies.hpp"

namespace dilatant {

// How the sweeps are accelerated (docs/model.md "Convergence"): none (plain
// projected Gauss–Seidel), or the nonsmooth nonlinear conjugate gradient of
// Silcowitz, Niebe & Erleben (2010, Vis. Comput. 26, 893): each sweep's change
// r of the impulses is taken as the (negative) gradient of a Fletcher–Reeves
// step, x <- x + beta d, d <- beta d + r, beta = |r|^2/|r_prev|^2, restarting
// (d <- r) when beta > 1. At the fixed point r = 0, so the answer is the
// Gauss–Seidel answer: the acceleration changes the path, never the solution.
enum class Acceleration : std::uint8_t { None, ConjugateGradient };

struct SolverSettings {
  double tolerance = 1e-6;  // on the relative impulse change of one sweep
  int max_iterations = 1000;
  int freeze_branches_after = 50;  // sweeps before each contact keeps its friction branch
  int threads = 1;                 // threads sharing a sweep (solver/slab_partition.hpp)
  // Over-relaxation of the normal impulse: p_n += omega (p_n_GS - p_n), kept >= 0.
  // 1 is plain Gauss–Seidel, the method itself (a single contact is exact after
  // one sweep: the closed-form tests rely on it); the fixed point does not
  // depend on omega.
  double relaxation = 1.0;
  Acceleration acceleration = Acceleration::None;
  // Sweeps in between full ones visit only the contacts that carried an impulse
  // after the last full sweep ("Open contacts" above; not with the acceleration).
  bool skip_open_contacts = false;
  // Fastest push-out of an overlap (solver/local_problem.hpp, gap_rate()): no cap
  // unless a driver that chooses dt from the fastest body sets one.
  double max_push_out = kNoPushOutCap;
  // What runs use unless solver.relaxation says otherwise: the same answer in
  // fewer sweeps (paper cell: 229 -> 145 with coulomb 0.3, 92 -> 74 with
  // stribeck at lambda 100); 1.6 stalls (bench/RESULTS.md).
  static constexpr double kRunRelaxation = 1.3;
};

struct SolveReport {
  int iterations = 0;           // sweeps, full and partial
  double contact_visits = 0.0;  // local solves over all sweeps (/contacts: sweep-equivalents)
  double residual = 0.0;
  bool converged = true;
};

// Sums accumulated over one sweep, from which the residual follows.
struct SweepChange {
  double change_squared = 0.0;   // sum |dP|^2
  double impulse_squared = 0.0;  // sum |P|^2
  double visits = 0.0;           // contacts visited
};

// With skip_open_contacts, every kFullSweepEvery-th sweep visits all contacts.
inline constexpr int kFullSweepEvery = 8;

// Adds M^-1 H P of the contacts' current impulses to the body velocities.
void apply_impulses(const std::vector<Contact>& contacts, Bodies& bodies);

// One Gauss–Seidel pass over all contacts in order.
SweepChange gauss_seidel_sweep(std::vector<Contact>& contacts, Bodies& bodies,
                               const FrictionLaw& law, double dt);

SolveReport solve_contacts(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                           double dt, const SolverSettings& settings);

// One step's contact problem: the contacts ordered in red-black slabs
// (solver/slab_partition.hpp), the bodies they act on, the law of contacts
// between particles, and the boundary, if any, whose contacts obey its own law.
struct ContactProblem {
  std::vector<Contact>& contacts;
  const SlabPartition& slabs;
  Bodies& bodies;
  const FrictionLaw& law;
  Boundary* boundary = nullptr;
  double dt = 0.0;
};

// The impulses do not depend on settings.threads.
SolveReport solve_contacts(const ContactProblem& problem, const SolverSettings& settings);

}  // namespace dilatant
