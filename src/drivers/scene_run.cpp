#include "drivers/scene_run.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "dilatant/version.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/scene_builder.hpp"
#include "io/atomic_file.hpp"
#include "io/contacts_csv.hpp"
#include "io/input_error.hpp"
#include "io/particles_csv.hpp"
#include "io/trajectory_writer.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

namespace {

// Running totals of the per-step solver and energy reports.
struct StepStatistics {
  long steps = 0;
  long unconverged = 0;
  long iterations_total = 0;
  int iterations_max = 0;
  double residual_max = 0.0;
  double overlap_max = 0.0;

  void add(const StepReport& r) {
    ++steps;
    if (!r.solve.converged) ++unconverged;
    iterations_total += r.solve.iterations;
    iterations_max = std::max(iterations_max, r.solve.iterations);
    residual_max = std::max(residual_max, r.solve.residual);
    overlap_max = std::max(overlap_max, r.max_overlap);
  }
};

nlohmann::json summary_json(const Config& config, const World& world, const TimeStepper& stepper,
                            const StepStatistics& s, double wall_time) {
  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "scene";
  j["particles"] = world.bodies.size();
  j["time"] = world.time;
  j["dt"] = stepper.dt();
  j["steps"] = s.steps;
  j["frac_steps_unconverged"] = s.steps > 0 ? double(s.unconverged) / double(s.steps) : 0.0;
  j["steps_unconverged"] = s.unconverged;
  j["solver_tolerance"] = config.solver.tolerance;
  j["solver_max_iterations"] = config.solver.max_iterations;
  j["mean_iterations"] = s.steps > 0 ? double(s.iterations_total) / double(s.steps) : 0.0;
  j["max_iterations_used"] = s.iterations_max;
  j["max_residual"] = s.residual_max;
  j["max_overlap"] = s.overlap_max;
  j["kinetic_energy"] = world.bodies.kinetic_energy();
  long closed = 0;
  for (const Contact& c : stepper.contacts()) closed += c.p_n > 0.0 ? 1 : 0;
  j["contacts"] = closed;
  j["mu0"] = config.friction.mu0;
  j["friction_law"] = config.friction.law == FrictionLawKind::Coulomb ? "coulomb" : "stribeck";
  j["wall_time_s"] = wall_time;
  return j;
}

}  // namespace

SceneOutcome run_scene(const Config& config, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SceneConfig& scene = *config.scene;
  World world = build_scene_world(config, read_particles_csv(scene.particles));
  const double dt = config.solver.dt > 0.0 ? config.solver.dt : automatic_time_step(world, config);
  if (dt > scene.trajectory_interval) {
    throw InputError(
        fmt::format("{}: scene.trajectory_interval = {} is shorter than solver.dt "
                    "= {}",
                    config.source, scene.trajectory_interval, dt));
  }
  TimeStepper stepper(make_friction_law(config.friction, config.fluid.eta_f),
                      make_solver_settings(config.solver), dt);

  std::filesystem::create_directories(options.out_dir);
  write_file_atomically(options.out_dir / "config.toml", resolved_toml(config));
  TrajectoryWriter trajectory(options.out_dir / "trajectory.csv");
  AtomicFileWriter timeseries(options.out_dir / "timeseries.csv");
  timeseries.write("step,t,contacts,iterations,residual,converged,kinetic_energy,max_overlap\n");

  const auto steps = static_cast<long>(std::ceil(config.run.time / dt - 1e-9));
  StepStatistics stats;
  trajectory.write_frame(world);
  double next_frame = scene.trajectory_interval;
  for (long n = 1; n <= steps; ++n) {
    const StepReport r = stepper.step(world);
    stats.add(r);
    timeseries.write(fmt::format("{},{:.10g},{},{},{:.3e},{},{:.10g},{:.3e}\n", n, world.time,
                                 r.contacts_closed, r.solve.iterations, r.solve.residual,
                                 r.solve.converged ? 1 : 0, r.kinetic_energy, r.max_overlap));
    // Frames fall on the first step at or past each multiple of the interval.
    if (world.time >= next_frame - 1e-9 * dt) {
      trajectory.write_frame(world);
      next_frame += scene.trajectory_interval *
                    std::floor((world.time - next_frame) / scene.trajectory_interval + 1.0 + 1e-9);
    }
  }
  trajectory.commit();
  timeseries.commit();
  write_file_atomically(options.out_dir / "contacts.csv",
                        contacts_csv(world.bodies, stepper.contacts(), dt));
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_file_atomically(options.out_dir / "summary.json",
                        summary_json(config, world, stepper, stats, wall).dump(2) + "\n");
  return SceneOutcome{stats.steps, stats.unconverged};
}

}  // namespace dilatant
