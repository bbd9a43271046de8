#include "solver/time_stepper.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <string>
#include <tuple>

namespace dilatant {

double TimeStepper::detection_margin(const World& world) const {
  // Two surfaces approach at most at the sum of their speeds; during the
  // solve an impulse can speed a body up, so allow twice the largest predicted
  // approach, plus a small floor so that resting contacts are always found.
  const Bodies& b = world.bodies;
  const ShearFlow flow = mean_flow_.value_or(ShearFlow{});
  double v_max = 0.0, r_max = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vec3 v = b.velocity[i];
    v[0] -= flow.shear_rate * (b.position[i][2] - flow.z0);
    v_max = std::max(v_max, v.norm() + b.radius[i] * b.angular_velocity[i].norm());
    r_max = std::max(r_max, b.radius[i]);
  }
  if (!mean_flow_) {
    // Images across a Lees–Edwards boundary move at +-shear_velocity besides.
    if (world.box.lees_edwards) v_max += std::abs(world.box.shear_velocity);
    return 4.0 * v_max * dt_ + 1e-3 * r_max;
  }
  // Relative to the mean flow u(z) (a Lees–Edwards image's included: its
  // drift is the flow's across Lz), bodies i, j whose surfaces are m apart
  // approach at most at 2 v_max + |gamma_dot| (2 R_max + m); twice that over
  // the step must stay within m:
  //     m = 4 dt (v_max + |gamma_dot| R_max) / (1 - 2 |gamma_dot| dt).
  const double shear = std::abs(flow.shear_rate);
  const double margin =
      4.0 * dt_ * (v_max + shear * r_max) / std::max(0.5, 1.0 - 2.0 * shear * dt_);
  return margin + 1e-3 * r_max;
}

void TimeStepper::warm_start(Bodies& bodies, double scale) {
  // The look-ups only read the memory: contacts are shared among the threads.
  const auto n = static_cast<std::int64_t>(contacts_.size());
  const int threads = settings_.threads;
#pragma omp parallel for schedule(static) num_threads(std::max(1, threads)) if (threads > 1)
  for (std::int64_t k = 0; k < n; ++k) {
    Contact& c = contacts_[static_cast<std::size_t>(k)];
    const auto it = memory_.find(contact_key(c));
    if (it == memory_.end()) continue;
    // The normal may have turned since the last step: keep the part of the old
    // impulse that is still compressive, and its tangential part in the new plane.
    const Vec3 p = scale * it->second.impulse;
    c.previous_regime = it->second.regime;
    c.p_n = std::max(0.0, p.dot(c.normal));
    c.p_t = p - p.dot(c.normal) * c.normal;
  }
  apply_impulses(contacts_, bodies);
}

void TimeStepper::relative_velocities(const Bodies& bodies, std::vector<Vec3>& out) const {
  out.resize(contacts_.size());
  const auto n = static_cast<std::int64_t>(contacts_.size());
  const int threads = settings_.threads;
#pragma omp parallel for schedule(static) num_threads(std::max(1, threads)) if (threads > 1)
  for (std::int64_t k = 0; k < n; ++k) {
    const auto ks = static_cast<std::size_t>(k);
    out[ks] = relative_velocity(contacts_[ks], bodies);
  }
}

std::pair<double, std::int32_t> TimeStepper::largest_overlap(const World& world) const {
  const Bodies& b = world.bodies;
  const auto n = static_cast<std::int64_t>(contacts_.size());
  const int threads = std::max(1, settings_.threads);
  // Each thread's deepest overlap over its static block of contacts; the
  // blocks are in order, so taking the first of equal depths below gives the
  // serial answer.
  std::vector<std::pair<double, std::int32_t>> deepest(static_cast<std::size_t>(threads),
                                                       {0.0, -1});
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    auto& mine = deepest[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) {
      const Contact& c = contacts_[static_cast<std::size_t>(k)];
      double gap;
      if (c.with_plane()) {
        gap = world.planes[c.plane_index()].distance(b.position[c.i]) - b.radius[c.i];
      } else {
        gap = world.box.minimum_image(b.position[c.i], b.position[c.other]).norm() - b.radius[c.i] -
              b.radius[c.other];
      }
      if (-gap > mine.first) mine = {-gap, static_cast<std::int32_t>(k)};
    }
  }
  std::pair<double, std::int32_t> out{0.0, -1};
  for (const auto& d : deepest)
    if (d.first > out.first) out = d;
  return out;
}

void TimeStepper::predict_detect_solve(World& world, Boundary* boundary, double warm_scale,
                                       StepReport& report) {
  Bodies& b = world.bodies;
  settings_.reference_impulse = reference_force_ * dt_;

  // 1. predict
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.is_fixed(i)) continue;
    Vec3 a = world.gravity;
    if (!world.external_force.empty()) a += b.inv_mass[i] * world.external_force[i];
    b.velocity[i] += dt_ * a;
  }
  if (boundary != nullptr) boundary->predict(b, dt_);
  // The kinetic energy before any force of the step's implicit problem (drag,
  // films, contacts) acts: their works add up to KE(end) minus this.
  report.kinetic_energy_free = b.kinetic_energy();
  drag_.clear();
  if (fluid_ != nullptr) {
    fluid_->body_drag(world, drag_);
    if (!drag_.empty()) implicit_drag_.predict(drag_, dt_, b);
  }

  // 2. detect, 3. warm start, 4. solve (with the effective masses of the
  // implicit drag, if any)
  using Clock = std::chrono::steady_clock;
  const auto detection_start = Clock::now();
  implicit_drag_.use_effective_masses(b);
  const double pair_range = fluid_ != nullptr ? fluid_->pair_range(world) : 0.0;
  detector_.detect(world, std::max(detection_margin(world), pair_range), contacts_,
                   settings_.threads);
  if (pair_range > 0.0) fluid_->pair_resistance(contacts_, dt_);
  slabs_ = partition_into_slabs(contacts_, world, scratch_);
  // The contacts' work is taken from the velocities before the drag acted
  // (fluid/implicit_drag.hpp), so that it and the drag's work add up exactly.
  if (implicit_drag_.active()) implicit_drag_.swap_predicted_velocities(b);
  relative_velocities(b, free_velocity_);
  if (implicit_drag_.active()) implicit_drag_.swap_predicted_velocities(b);
  warm_start(b, warm_scale);
  const auto solve_start = Clock::now();
  if (boundary != nullptr) boundary->begin_solve(contacts_, b);
  // The one context the solve's stages and the residual are handed.
  const ContactProblem problem{.contacts = contacts_,
                               .slabs = slabs_,
                               .bodies = b,
                               .law = law_,
                               .boundary = boundary,
                               .dt = dt_,
                               .settings = settings_,
                               .observer = pass_observer_ ? &pass_observer_ : nullptr};
  report.solve = solve_contacts(problem);
  // The residual of the final impulses: the one the stopping test evaluated
  // there, if it did (solver/contact_solver.hpp), else computed now; under
  // Residual the solve's reported value is that residual.
  report.contact_residual =
      report.solve.final_residual_known ? report.solve.final_residual : contact_residual(problem);
  if (settings_.convergence == Convergence::Residual)
    report.solve.residual = report.contact_residual.max();
  implicit_drag_.restore_masses(b);
  if (!drag_.empty()) report.drag_work = implicit_drag_.work(drag_, dt_, b);

  const auto solve_end = Clock::now();
  report.detection_seconds += std::chrono::duration<double>(solve_start - detection_start).count();
  report.solve_seconds += std::chrono::duration<double>(solve_end - solve_start).count();
}

void TimeStepper::fail(const World& world, const StepReport& report) const {
  const Bodies& b = world.bodies;
  std::string where = "no contact";
  if (const std::int32_t k = report.contact_residual.worst_contact; k >= 0) {
    const Contact& c = contacts_[static_cast<std::size_t>(k)];
    // A driven body says whose it is (boundary/wall_owner.hpp: 1 bottom wall, 2 top wall).
    const auto body = [&](std::size_t i) {
      return b.owner[i] == kNoOwner ? fmt::format("{}", b.id[i])
                                    : fmt::format("{} (boundary part {})", b.id[i], b.owner[i]);
    };
    where = c.with_plane() ? fmt::format("body id {} and plane {}", body(c.i), c.plane_index())
                           : fmt::format("body ids {} and {}", body(c.i), body(c.other));
  }
  throw SolveFailure(fmt::format(
      "the contact solve did not converge at t = {:.6g}, not even at the shortest step dt = {:.3g} "
      "({} halvings): residual {:.3g} (solver.tolerance {:.3g}) after {} sweeps, worst at the "
      "contact of {}",
      world.time, dt_, report.redos, report.contact_residual.max(), settings_.tolerance,
      report.solve.iterations, where));
}

StepReport TimeStepper::step(World& world, Boundary* boundary) {
  Bodies& b = world.bodies;
  StepReport report;
  // A redo starts from the state before stage 1 (the memory of stage 5 and
  // the positions are not yet touched).
  const bool may_redo = settings_.redo_unconverged && shortest_dt_ > 0.0;
  if (may_redo) {
    saved_velocity_ = b.velocity;
    saved_angular_velocity_ = b.angular_velocity;
    if (boundary != nullptr) boundary->save_state();
  }
  for (double warm_scale = 1.0;; warm_scale *= 0.5) {
    predict_detect_solve(world, boundary, warm_scale, report);
    if (report.solve.converged || !may_redo) break;
    // Undo the attempt: the bodies and the boundary as before stage 1 (also
    // before a failure, so that the caller holds the last accepted state).
    b.velocity = saved_velocity_;
    b.angular_velocity = saved_angular_velocity_;
    if (boundary != nullptr) boundary->restore_state();
    // Halving past the shortest step (with round-off's allowance) fails.
    if (0.5 * dt_ < shortest_dt_ * (1.0 - 1e-9)) fail(world, report);
    if (!contacts_.empty())
      report.redone_sweep_equivalents +=
          report.solve.contact_visits / static_cast<double>(contacts_.size());
    ++report.redos;
    report.drag_work = 0.0;
    dt_ *= 0.5;
  }
  report.dt = dt_;

  // 5. store impulses of the contacts that carry load
  memory_.clear();
  for (const Contact& c : contacts_) {
    if (c.p_n <= 0.0) continue;
    memory_.emplace(contact_key(c), ContactMemory{c.p_n * c.normal + c.p_t, c.regime});
    ++report.contacts_closed;
  }
  report.contacts_detected = contacts_.size();
  relative_velocities(b, end_velocity_);
  report.contact_work = contact_work(contacts_, free_velocity_, end_velocity_);

  // 6. integrate positions with the end-of-step velocities (a body of infinite
  // mass may still move at a prescribed velocity: a driven body); a body
  // leaving through a Lees–Edwards boundary re-enters where the copies have
  // moved to at the step's end.
  world.box.advance_shear(dt_);
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.position[i] += dt_ * b.velocity[i];
    world.box.wrap_body(b.position[i], b.velocity[i]);
  }
  world.time += dt_;
  report.kinetic_energy = b.kinetic_energy();
  std::tie(report.max_overlap, report.max_overlap_contact) = largest_overlap(world);
  // Never a silent bad number: a body whose state is no longer finite stops
  // the run here, named, before anything reads it.
  if (const std::ptrdiff_t bad = b.first_non_finite(); bad >= 0)
    throw NumericalFault(fmt::format(
        "numerical fault at t = {:.6g}: body {} (id {}) has a non-finite position, velocity or "
        "spin",
        world.time, bad, b.id[static_cast<std::size_t>(bad)]));
  return report;
}

}  // namespace dilatant
