#pragma once
// How far the impulses of a step are from solving its contact problem — not
// how much they changed in the last pass, which can be small while the
// iteration still crawls (a jammed packing creeps that way).
//
// For each contact c, let P_c* = (p_n*, p_t*) be the exact solution of its local
// problem with every other contact frozen at its current impulse
// (solver/local_problem.hpp; the friction branch is the one the contact is on:
// stick/BL on the mu0 cone, HD on the lubrication curve). P solves the whole
// problem if and only if P_c = P_c* for every c (the natural-map residual of the
// complementarity problem, Jean 1999; Acary & Brogliato 2008, ch. 13). Its parts:
//
//   normal      |p_n* - p_n|: the violation of non-penetration and of
//               complementarity, an approach speed |u_n + g/dt| times 1/w_n;
//   tangential  |p_t* - p_t|: the violation of the cone (stick) or of the
//               friction law (|P_t| = mu(s) p_n opposite the slip).
//
// Each is reported as a maximum and an RMS over the contacts, in units of the
// problem's reference impulse P_ref (SolverSettings::reference_impulse: in the
// shear cell tau (2 R_max)^2 dt, the impulse the applied stress puts on a
// particle's cross-section in one step), or without one relative to the RMS
// impulse of the loaded contacts, sqrt(sum |P_c|^2 / n_loaded). A residual of
// 1e-2 then means the worst contact is off by 1% of P_ref. Changes below the
// round-off of recomputing an impulse from the velocities (16 eps |v|_c / w_n,
// as the relative change's floor in solver/contact_solver.hpp) do not count.
//
// With SolverSettings::convergence = Residual this is the solver's stopping
// test (solver/contact_solver.cpp evaluates it slab by slab inside its own
// parallel region); with Change it shows what that test bought.
#include <cstdint>
#include <span>
#include <vector>

#include "solver/contact_problem.hpp"

namespace dilatant {

struct ContactResidual {
  double normal_max = 0.0, normal_rms = 0.0;
  double tangential_max = 0.0, tangential_rms = 0.0;
  // The contact that holds max() (its index in the contacts), so that a step
  // that did not converge names where (-1: no contacts, or none off at all).
  std::int32_t worst_contact = -1;
  // The RMS impulse of the loaded contacts in the same unit (1 without a
  // reference impulse): what "a typical impulse" is against P_ref.
  double typical_impulse = 0.0;
  double max() const { return normal_max > tangential_max ? normal_max : tangential_max; }
};

// The residual of the problem's current impulses (the contacts of each
// slab's boundary range under the boundary's law), reading the bodies'
// current velocities. Reads only; settings.threads share the slabs, with the
// same result for any number of them. Overlaps are measured against the
// push-out the solver was allowed (settings.max_push_out,
// solver/local_problem.hpp).
ContactResidual contact_residual(const ContactProblem& problem);

// The same in two stages, for a caller that already runs threads: the sums of
// one slab (any thread), then the residual of all slabs' sums, added in slab
// order (the same bits whatever thread computed which slab).
struct ResidualSums {
  double normal_max = 0.0, normal_squared = 0.0;
  double tangential_max = 0.0, tangential_squared = 0.0;
  double impulse_squared = 0.0;   // of the loaded contacts ...
  double loaded = 0.0;            // ... and their number
  double worst = 0.0;             // max(normal_max, tangential_max) ...
  std::int32_t worst_index = -1;  // ... at this contact
};
ResidualSums slab_residual(const ContactProblem& problem, int slab);
ContactResidual combine_residual(const ContactProblem& problem,
                                 std::span<const ResidualSums> per_slab);

}  // namespace dilatant
