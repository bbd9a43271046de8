#include "solver/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace dilatant {

namespace {

// Which contacts of a range a pass visits (see "Open contacts" in the header):
// every one, listing in `loaded` (if given) those that end the pass with an
// impulse; or, if `only` is given, only those it lists.
struct Visits {
  const std::vector<std::int32_t>* only = nullptr;
  std::vector<std::int32_t>* loaded = nullptr;
};

// What one pass shares over all its slabs: the problem, whether the friction
// branches are frozen yet, and where each contact's impulse change goes (the
// acceleration's; null: nowhere).
struct Pass {
  const ContactProblem& problem;
  double relaxation = 1.0;  // of this pass (relaxation_at_pass())
  bool freeze_branches = false;
  Vec3* changes = nullptr;
  // The boundary's degree of freedom solved inside the pass (boundary.hpp),
  // for the boundary ranges only; null: none.
  WallBlock* wall = nullptr;
};

// Contact c's side of the wall block: +1 if body i is the wall's, -1 if its
// partner is, 0 if neither (the impulse on the wall is sign P).
double wall_side(const Contact& c, const Bodies& b, const WallBlock& wall) {
  if (b.owner[c.i] == wall.owner) return 1.0;
  if (!c.with_plane() && b.owner[c.other] == wall.owner) return -1.0;
  return 0.0;
}

// One pass over `contacts`, which start at index `first` of the problem's.
// The hot loop: the pass's scalars are copied into locals first, as the
// compiler cannot tell the bodies' doubles it stores to from the problem's it
// would otherwise read back from memory after every store.
template <bool kWall, class Law>
PassChange relax(std::span<Contact> contacts, std::size_t first, const Law& law, const Pass& pass,
                 Visits visits) {
  Bodies& b = pass.problem.bodies;
  const double dt = pass.problem.dt, inv_dt = 1.0 / dt;
  const double relaxation = pass.relaxation;
  const double max_push_out = pass.problem.settings.max_push_out;
  const bool freeze_branches = pass.freeze_branches;
  Vec3* const changes = pass.changes != nullptr ? pass.changes + first : nullptr;
  std::vector<std::int32_t>* const loaded = visits.loaded;
  PassChange change;
  WallBlock* const wall = pass.wall;
  const auto visit = [&](std::size_t k) {
    Contact& c = contacts[k];
    // On the wall (boundary.hpp): its body moves at the block's current V, and
    // the local problem sees the wall's compliance as well as the particle's.
    // The rank-1 term a a^T / M (a = sign e_x) is bounded by its diagonal in
    // the contact frame, w_n += n_x^2 / M, w_t += (1 - n_x^2) / M: exact
    // normally, slightly under-relaxed tangentially, and the same fixed point
    // (docs/shear-cell.md "Dynamics").
    double side = 0.0;
    const Contact* local = &c;
    [[maybe_unused]] Contact local_copy;  // unused, and optimised away, without a wall
    if constexpr (kWall) side = wall_side(c, b, *wall);
    if (side != 0.0) {
      b.velocity[side > 0.0 ? c.i : c.other] = Vec3(wall->velocity, 0.0, 0.0);
      local_copy = c;
      const double nx2 = c.normal[0] * c.normal[0];
      local_copy.w_n += nx2 * wall->inv_mass;
      local_copy.w_t += (1.0 - nx2) * wall->inv_mass;
      local = &local_copy;
    }
    const LocalAnswer a = solve_local(*local, b, law, dt, inv_dt, relaxation,
                                      imposed_branch(c, freeze_branches), max_push_out);
    const double p_n = a.p_n;
    const Vec3& p_t = a.p_t;
    const TangentialSolution& t = a.tangential;
    // The film and the contact act along the same normal: their sum is the
    // pair's normal impulse, whose change the tolerance measures.
    const double normal = p_n + a.p_lub;
    const Vec3 dp = (normal - c.p_n - c.p_lub) * c.normal + (p_t - c.p_t);
    apply_impulse(c, dp, b);
    if (side != 0.0) wall->velocity += side * dp[0] * wall->inv_mass;
    if (changes != nullptr) changes[k] = dp;
    c.p_n = p_n;
    c.p_t = p_t;
    c.p_lub = a.p_lub;
    c.sliding_speed = t.sliding_speed;
    c.sommerfeld = t.sommerfeld;
    c.regime = t.regime;
    const double dp_squared = dp.squaredNorm();
    change.change_squared += dp_squared;
    change.max_change_squared = std::max(change.max_change_squared, dp_squared);
    change.impulse_squared += normal * normal + p_t.squaredNorm();
    if (p_n > 0.0 || a.p_lub != 0.0 || p_t.squaredNorm() > 0.0) {
      change.loaded += 1.0;
      if (loaded != nullptr) loaded->push_back(static_cast<std::int32_t>(k));
    }
  };
  if (visits.only == nullptr) {
    if (loaded != nullptr) loaded->clear();
    for (std::size_t k = 0; k < contacts.size(); ++k) visit(k);
  } else {
    for (const std::int32_t k : *visits.only) visit(static_cast<std::size_t>(k));
  }
  return change;
}

// The problem's contacts [begin, end) under `law`: the one dispatch on the
// law's kind per range, so that the per-contact call stays inlined.
PassChange relax_range(const Pass& pass, std::size_t begin, std::size_t end, const FrictionLaw& law,
                       Visits visits) {
  const std::span<Contact> part(pass.problem.contacts.data() + begin, end - begin);
  return std::visit(
      [&](const auto& l) {
        return pass.wall != nullptr ? relax<true>(part, begin, l, pass, visits)
                                    : relax<false>(part, begin, l, pass, visits);
      },
      law);
}

}  // namespace

double relaxation_at_pass(const SolverSettings& settings, int pass) {
  return 2 * pass < settings.max_iterations ? settings.relaxation : 1.0;
}

void apply_impulses(const std::vector<Contact>& contacts, Bodies& bodies) {
  for (const Contact& c : contacts) apply_impulse(c, (c.p_n + c.p_lub) * c.normal + c.p_t, bodies);
}

namespace {

// Round-off floor of a pass's impulse changes (see the header): its sum of
// squares over the contacts, and its largest.
struct RoundOff {
  double squared = 0.0, max = 0.0;
};
RoundOff round_off_floor(const std::vector<Contact>& contacts, const Bodies& bodies) {
  RoundOff floor;
  for (const Contact& c : contacts) {
    const double noise = round_off_impulse(c, bodies);
    floor.squared += noise * noise;
    floor.max = std::max(floor.max, noise);
  }
  return floor;
}

// The conjugate-gradient step of the nonsmooth nonlinear CG method (see
// solver/contact_problem.hpp): with r the change of the pass just done and
// beta = |r|^2 / |r_prev|^2, move every impulse on along the previous
// direction by beta d, then d <- beta d + r. beta > 1 (the pass went uphill)
// restarts: d <- r.
void conjugate_gradient_step(std::vector<Contact>& contacts, Bodies& bodies,
                             const std::vector<Vec3>& changes, std::vector<Vec3>& direction,
                             double beta) {
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    Contact& c = contacts[k];
    if (beta > 0.0) {
      const Vec3 step = beta * direction[k];
      const double step_n = step.dot(c.normal);
      // A pair with a squeeze film: the step moves the film's impulse, and the
      // next visit splits the normal impulse between film and contact exactly.
      (c.lubrication > 0.0 ? c.p_lub : c.p_n) += step_n;
      c.p_t += step - step_n * c.normal;
      apply_impulse(c, step, bodies);
      direction[k] = step + changes[k];
    } else {
      direction[k] = changes[k];
    }
  }
}

}  // namespace

PassChange gauss_seidel_pass(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                             double dt) {
  static const SolverSettings plain{};  // relaxation 1, no push-out cap
  const SlabPartition slabs = SlabPartition::single(contacts.size(), contacts.size());
  const ContactProblem problem{.contacts = contacts,
                               .slabs = slabs,
                               .bodies = bodies,
                               .law = law,
                               .dt = dt,
                               .settings = plain};
  return relax_range({.problem = problem}, 0, contacts.size(), law, {});
}

SolveReport solve_contacts(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                           double dt, const SolverSettings& settings) {
  const SlabPartition slabs = SlabPartition::single(contacts.size(), contacts.size());
  return solve_contacts({.contacts = contacts,
                         .slabs = slabs,
                         .bodies = bodies,
                         .law = law,
                         .boundary = nullptr,
                         .dt = dt,
                         .settings = settings});
}

SolveReport solve_contacts(const ContactProblem& problem) {
  std::vector<Contact>& contacts = problem.contacts;
  const SlabPartition& slabs = problem.slabs;
  Bodies& bodies = problem.bodies;
  const SolverSettings& settings = problem.settings;
  const FrictionLaw& boundary_law = problem.boundary_law();
  Boundary* const boundary = problem.boundary;
  // Only the last slab's boundary range touches the wall's bodies
  // (solver/slab_partition.hpp), so one thread at a time moves it.
  WallBlock* const wall = boundary != nullptr ? boundary->coupled_block() : nullptr;
  SolveReport report;
  if (boundary != nullptr) boundary->solve_block(contacts, bodies);
  if (contacts.empty()) return report;
  report.converged = false;
  const RoundOff round_off = round_off_floor(contacts, bodies);
  const int n = slabs.count();
  // Two buffers of per-slab sums, by pass parity: a thread that has finished a
  // pass may already write the next pass's sums while another still reads.
  std::vector<PassChange> partial(2 * static_cast<std::size_t>(n));
  const bool by_residual = settings.convergence == Convergence::Residual;
  std::vector<ResidualSums> residual_sums(by_residual ? static_cast<std::size_t>(n) : 0);
  const bool accelerate = settings.acceleration == Acceleration::ConjugateGradient;
  std::vector<Vec3> changes, direction;
  if (accelerate) {
    changes.assign(contacts.size(), Vec3::Zero());
    direction.assign(contacts.size(), Vec3::Zero());
  }
  double change_before = 0.0;  // |r|^2 of the previous pass
  // Skipping open contacts (header): per slab, the contacts of its particle and
  // its boundary range that carried an impulse after the last full pass.
  const bool skip_open = settings.skip_open_contacts && !accelerate;
  std::vector<std::vector<std::int32_t>> loaded(skip_open ? 2 * static_cast<std::size_t>(n) : 0);
  const auto relax_slab = [&](int k, int pass_index, bool freeze, bool full) {
    const auto ks = static_cast<std::size_t>(k);
    const Pass pass{.problem = problem,
                    .relaxation = relaxation_at_pass(settings, pass_index),
                    .freeze_branches = freeze,
                    .changes = accelerate ? changes.data() : nullptr};
    std::vector<std::int32_t>* list = skip_open ? &loaded[2 * ks] : nullptr;
    std::vector<std::int32_t>* list_boundary = skip_open ? &loaded[2 * ks + 1] : nullptr;
    const auto visits = [full](std::vector<std::int32_t>* l) {
      return full ? Visits{.only = nullptr, .loaded = l} : Visits{.only = l, .loaded = nullptr};
    };
    const std::size_t mid = slabs.boundary_begin[ks];
    const PassChange ch = relax_range(pass, slabs.begin[ks], mid, problem.law, visits(list));
    Pass boundary_pass = pass;
    boundary_pass.wall = wall;
    const PassChange ch_boundary =
        relax_range(boundary_pass, mid, slabs.begin[ks + 1], boundary_law, visits(list_boundary));
    const std::size_t visited =
        full ? slabs.begin[ks + 1] - slabs.begin[ks] : list->size() + list_boundary->size();
    partial[static_cast<std::size_t>((pass_index & 1) * n + k)] = {
        .change_squared = ch.change_squared + ch_boundary.change_squared,
        .impulse_squared = ch.impulse_squared + ch_boundary.impulse_squared,
        .visits = static_cast<double>(visited),
        .max_change_squared = std::max(ch.max_change_squared, ch_boundary.max_change_squared),
        .loaded = ch.loaded + ch_boundary.loaded};
  };
  // A finished pass's sums, added in a fixed slab order, so that every thread
  // computes the same values whatever the thread count.
  const auto pass_sums = [&](int pass_index) {
    PassChange ch;
    for (int k = 0; k < n; ++k) {
      const PassChange& p = partial[static_cast<std::size_t>((pass_index & 1) * n + k)];
      ch.change_squared += p.change_squared;
      ch.impulse_squared += p.impulse_squared;
      ch.visits += p.visits;
      ch.max_change_squared = std::max(ch.max_change_squared, p.max_change_squared);
      ch.loaded += p.loaded;
    }
    return ch;
  };
  // Change: the relative change of the pass (the header's formula).
  const auto relative_change = [&](const PassChange& ch) {
    const double change_squared = std::max(0.0, ch.change_squared - round_off.squared);
    return ch.impulse_squared > 0.0 ? std::sqrt(change_squared / ch.impulse_squared)
                                    : (change_squared > 0.0 ? 1.0 : 0.0);
  };
  // Residual: whether the pass's largest change lets the residual hold (the
  // header's trigger), in the residual's unit (solver/contact_residual.hpp).
  const auto triggered = [&](const PassChange& ch) {
    const double unit = settings.reference_impulse > 0.0
                            ? settings.reference_impulse
                            : (ch.loaded > 0.0 ? std::sqrt(ch.impulse_squared / ch.loaded) : 0.0);
    const double largest = std::sqrt(ch.max_change_squared);
    return largest <= std::max(kResidualTrigger * settings.tolerance * unit, round_off.max);
  };
  const int threads = std::max(1, std::min(settings.threads, n / 2));
  // Two barriers per pass (the ends of the two `omp for`). The boundary's block
  // is solved by one thread while the others start the next even half: only
  // the last slab, which is odd, touches the bodies the block writes
  // (boundary/boundary.hpp, solver/slab_partition.hpp).
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    // Every thread keeps these alike, as they follow from sums all of them
    // compute in the same order: whether the next pass visits every contact,
    // and under Residual the first pass that may evaluate the residual and the
    // deferral after a failed evaluation.
    bool full = true;
    int next_evaluation = 0, deferral = 1;
    for (int pass = 0; pass < settings.max_iterations; ++pass) {
      const bool freeze = pass >= settings.freeze_branches_after;
#pragma omp for schedule(static)
      for (int k = 0; k < n; k += 2) relax_slab(k, pass, freeze, full);
#pragma omp for schedule(static)
      for (int k = 1; k < n; k += 2) relax_slab(k, pass, freeze, full);
      const PassChange sums = pass_sums(pass);
      const double change = relative_change(sums);
      // met: the pass passes the cheap test (Change: the test itself).
      const bool met = by_residual ? triggered(sums) : change <= settings.tolerance;
      const bool evaluate = by_residual && met && full && pass >= next_evaluation;
#pragma omp masked
      {
        if (boundary != nullptr) boundary->solve_block(contacts, bodies);
        report.iterations = pass + 1;
        if (!by_residual) report.residual = change;
        report.converged = !by_residual && met && full;
        report.contact_visits += sums.visits;
      }
      bool converged = !by_residual && met && full;
      if (evaluate) {
        // After the boundary's block: the residual of the impulses and
        // velocities the pass ends with, as the stepper would report them.
#pragma omp barrier
#pragma omp for schedule(static)
        for (int k = 0; k < n; ++k)
          residual_sums[static_cast<std::size_t>(k)] = slab_residual(problem, k);
        const ContactResidual r = combine_residual(problem, residual_sums);
        converged = r.max() <= settings.tolerance;
        if (!converged) {
          next_evaluation = pass + deferral;
          deferral = std::min(2 * deferral, kLongestDeferral);
        }
#pragma omp masked
        {
          report.residual = r.max();
          report.converged = converged;
          report.final_residual_known = true;
          report.final_residual = r;
          report.contact_visits += static_cast<double>(contacts.size());
        }
      }
      // The observer sees the impulses a pass ends with (after the
      // acceleration's step, if any); every thread takes the same branch.
      const auto observe = [&] {
        if (problem.observer == nullptr) return;
#pragma omp barrier
#pragma omp single
        (*problem.observer)(problem, report.iterations, report.contact_visits);
      };
      // Only a full pass can end the solve: a partial one has not looked at
      // the skipped contacts, so meeting the tolerance there calls for a full one.
      if (converged) {
        observe();
        break;
      }
      full = !skip_open || (met && pass + 1 >= next_evaluation) || (pass + 1) % kFullPassEvery == 0;
      if (accelerate) {
        // Serial, and behind barriers: the step touches every contact's bodies.
#pragma omp barrier
#pragma omp single
        {
          const double beta =
              pass > 0 && change_before > 0.0 ? sums.change_squared / change_before : 2.0;
          conjugate_gradient_step(contacts, bodies, changes, direction, beta <= 1.0 ? beta : 0.0);
          change_before = sums.change_squared;
          if (boundary != nullptr) boundary->solve_block(contacts, bodies);
        }
      }
      observe();
    }
  }
  // A residual evaluated before later passes moved the impulses is not theirs.
  if (report.final_residual_known && !report.converged) report.final_residual_known = false;
  return report;
}

}  // namespace dilatant
