#pragma once
// One step's contact problem and the settings it is solved with: the one
// context every stage of the solve is handed (solver/contact_solver.hpp:
// the first solve of the boundary's block, the relaxation passes slab by
// slab, the acceleration's step; solver/contact_residual.hpp: the residual
// of the impulses the solve ended with), as Box2D v3 hands one b2StepContext
// (src/solver.h) to its prepare, warm start, solve and store stages instead
// of a dozen arguments to each.
//
// The problem does not own what it names: the stepper (solver/time_stepper.hpp)
// owns the contacts, their slab order and the settings, the world the bodies.
#include <cstdint>
#include <functional>
#include <vector>

#include "boundary/boundary.hpp"
#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "solver/local_problem.hpp"
#include "solver/slab_partition.hpp"
#include "world/bodies.hpp"

namespace dilatant {

// How the passes are accelerated (docs/model.md "Convergence"): none (plain
// projected Gauss–Seidel), or the nonsmooth nonlinear conjugate gradient of
// Silcowitz, Niebe & Erleben (2010, Vis. Comput. 26, 893): each pass's change
// r of the impulses is taken as the (negative) gradient of a Fletcher–Reeves
// step, x <- x + beta d, d <- beta d + r, beta = |r|^2/|r_prev|^2, restarting
// (d <- r) when beta > 1. At the fixed point r = 0, so the answer is the
// Gauss–Seidel answer: the acceleration changes the path, never the solution.
enum class Acceleration : std::uint8_t { None, ConjugateGradient };

// What ends the passes (solver/contact_solver.hpp, docs/model.md "Convergence
// criterion"):
//   Residual  the contact problem's residual (solver/contact_residual.hpp): no
//             contact's impulse is further than tolerance x reference_impulse
//             from the exact answer of its local problem. A self-stress
//             locked into a jammed packing cannot mask it.
//   Change    the relative change of all impulses in one pass (the test of
//             versions before 0.7): sqrt(sum |dP|^2 / sum |P|^2) <= tolerance.
//             A large self-stress inflates sum |P|^2 and can meet it far from
//             the answer; kept for old configurations and unit tests of the
//             iteration itself.
enum class Convergence : std::uint8_t { Residual, Change };

// A pass is one Gauss–Seidel sweep over the contacts; the configuration and
// the outputs keep the word "sweep" (solver.max_sweeps, sweep_equivalents).
struct SolverSettings {
  Convergence convergence = Convergence::Change;
  double tolerance = 1e-6;  // in the unit of the test above
  // The residual's unit, an impulse the driver sets per step from the load it
  // applies (the shear cell: tau (2 R_max)^2 dt; a scene: the heaviest
  // body's weight times dt). 0: the RMS impulse of the loaded contacts, which
  // a self-stress inflates as it does the relative change.
  double reference_impulse = 0.0;
  int max_iterations = 1000;
  int freeze_branches_after = 50;  // passes before each contact keeps its friction branch
  int threads = 1;                 // threads sharing a pass (solver/slab_partition.hpp)
  // Over-relaxation of the normal impulse: p_n += omega (p_n_GS - p_n), kept >= 0.
  // 1 is plain Gauss–Seidel, the method itself (a single contact is exact after
  // one pass: the closed-form tests rely on it); the fixed point does not
  // depend on omega.
  double relaxation = 1.0;
  Acceleration acceleration = Acceleration::None;
  // Passes in between full ones visit only the contacts that carried an impulse
  // after the last full pass ("Open contacts", solver/contact_solver.hpp; not
  // with the acceleration).
  bool skip_open_contacts = false;
  // Fastest push-out of an overlap (solver/local_problem.hpp, gap_rate()): no cap
  // unless a driver that chooses dt from the fastest body sets one.
  double max_push_out = kNoPushOutCap;
  // A step whose solve ends unconverged is undone and redone at half its
  // length, down to the driver's shortest step, and then stops the run
  // (solver/time_stepper.hpp); false: it is accepted, and reported.
  bool redo_unconverged = false;
  // What runs use unless solver.relaxation says otherwise: the same answer in
  // fewer passes (paper cell: 229 -> 145 with coulomb 0.3, 92 -> 74 with
  // stribeck at lambda 100); 1.6 stalls (bench/RESULTS.md).
  static constexpr double kRunRelaxation = 1.3;
};

struct ContactProblem;
// Called after every pass of the solve, by one thread while the others wait,
// with the passes so far and the local solves they took (the contact visits):
// a method's work against its residual, measured by a tool that solves a
// step's problem again (bench/solve_step.cpp). Not for runs: it costs a
// barrier per pass.
using PassObserver = std::function<void(const ContactProblem&, int passes, double visits)>;

// The contacts ordered in red-black slabs (solver/slab_partition.hpp), the
// bodies they act on, the law of contacts between dynamic bodies, the
// boundary, if any, whose law the contacts touching a driven body obey, the
// step's dt, and the settings.
struct ContactProblem {
  std::vector<Contact>& contacts;
  const SlabPartition& slabs;
  Bodies& bodies;
  const FrictionLaw& law;
  Boundary* boundary = nullptr;
  double dt = 0.0;
  const SolverSettings& settings;
  const PassObserver* observer = nullptr;  // none in runs

  // The law of the contacts in each slab's boundary range: the boundary's, or
  // without one the particles' (a driven body nobody moves is an obstacle).
  const FrictionLaw& boundary_law() const {
    return boundary != nullptr ? boundary->contact_law() : law;
  }
};

}  // namespace dilatant
