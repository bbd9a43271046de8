#include "drivers/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dilatant/version.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/scene_builder.hpp"
#include "io/input_error.hpp"
#include "io/particles_csv.hpp"

namespace dilatant {

void StepStatistics::add(const StepReport& r) {
  ++steps;
  if (!r.solve.converged) ++unconverged;
  if (r.redos > 0) ++redone;
  iterations_total += r.solve.iterations;
  iterations_max = std::max(iterations_max, r.solve.iterations);
  residual_max = std::max(residual_max, r.solve.residual);
  contact_residual_max = std::max(contact_residual_max, r.contact_residual.max());
  overlap_max = std::max(overlap_max, r.max_overlap);
}

namespace {

World scene_world(const Config& config) {
  return build_scene_world(config, read_particles_csv(config.scene()->particles));
}

double scene_dt(const Config& config, const World& world) {
  const double dt = config.solver.dt > 0.0 ? config.solver.dt : automatic_time_step(world, config);
  if (dt > config.scene()->trajectory_interval) {
    throw InputError(
        fmt::format("{}: scene.trajectory_interval = {} is shorter than solver.dt = {}",
                    config.source, config.scene()->trajectory_interval, dt));
  }
  return dt;
}

}  // namespace

Scene::Scene(Config config)
    : config_(std::move(config)),
      world_(scene_world(config_)),
      stepper_(make_friction_law(config_.friction, config_.fluid.eta_f, config_.critical_load()),
               make_solver_settings(config_.solver), scene_dt(config_, world_)),
      fluid_(make_fluid(config_.fluid, config_.fluid.eta_f)) {
  stepper_.set_fluid_forces(fluid_.get());  // a fluid at rest (ShearFlow's default)
  stepper_.set_reference_force(weight_force(world_));
  dt_ = stepper_.dt();
  stepper_.set_shortest_dt(dt_ / kShortestStepDivisor);
  total_steps_ = static_cast<long>(std::ceil(config_.run.time / dt_ - 1e-9));
}

const StepReport& Scene::step() {
  if (rest_of_step_ <= 0.0) rest_of_step_ = dt_;
  stepper_.set_dt(rest_of_step_);
  last_ = stepper_.step(world_);
  statistics_.add(last_);
  rest_of_step_ -= last_.dt;
  // A rest below round-off of dt ends the whole step.
  if (rest_of_step_ <= 1e-9 * dt_) {
    rest_of_step_ = 0.0;
    ++whole_steps_;
  }
  return last_;
}

SceneProgress Scene::progress() const {
  const Bodies& b = world_.bodies;
  return SceneProgress{b.position,   b.velocity,    b.angular_velocity, world_.time,
                       whole_steps_, rest_of_step_, statistics_,        stepper_.contact_memory()};
}

void Scene::restore(SceneProgress p) {
  Bodies& b = world_.bodies;
  const std::size_t n = b.size();
  if (p.position.size() != n || p.velocity.size() != n || p.angular_velocity.size() != n)
    throw std::runtime_error(
        fmt::format("a state of {} bodies restored into a scene of {}", p.position.size(), n));
  b.position = std::move(p.position);
  b.velocity = std::move(p.velocity);
  b.angular_velocity = std::move(p.angular_velocity);
  world_.time = p.time;
  whole_steps_ = p.whole_steps;
  rest_of_step_ = p.rest_of_step;
  statistics_ = p.statistics;
  stepper_.restore_contact_memory(std::move(p.contact_memory));
}

nlohmann::json Scene::summary(double wall_time) const {
  const StepStatistics& s = statistics_;
  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "scene";
  j["particles"] = world_.bodies.size();
  j["time"] = world_.time;
  j["dt"] = dt_;
  j["steps"] = s.steps;
  j["frac_steps_unconverged"] = s.steps > 0 ? double(s.unconverged) / double(s.steps) : 0.0;
  j["steps_unconverged"] = s.unconverged;
  j["steps_redone"] = s.redone;  // at a shorter step (solver/time_stepper.hpp)
  j["solver_tolerance"] = config_.solver.tolerance;
  j["solver_max_iterations"] = config_.solver.max_iterations;
  j["mean_iterations"] = s.steps > 0 ? double(s.iterations_total) / double(s.steps) : 0.0;
  j["max_iterations_used"] = s.iterations_max;
  j["max_residual"] = s.residual_max;
  j["contact_residual_max"] = s.contact_residual_max;
  j["max_overlap"] = s.overlap_max;
  j["kinetic_energy"] = world_.bodies.kinetic_energy();
  long closed = 0;
  for (const Contact& c : stepper_.contacts()) closed += c.p_n > 0.0 ? 1 : 0;
  j["contacts"] = closed;
  j["mu0"] = config_.friction.mu0;
  j["friction_law"] = friction_law_name(config_.friction.law);
  j["critical_load"] = config_.friction.critical_load;
  j["wall_time_s"] = wall_time;
  return j;
}

}  // namespace dilatant
