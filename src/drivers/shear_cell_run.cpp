#include "drivers/shear_cell_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "drivers/model_setup.hpp"
#include "drivers/shear_cell_summary.hpp"
#include "io/atomic_file.hpp"
#include "io/contacts_csv.hpp"
#include "io/vtk_writer.hpp"
#include "measure/bulk_fraction.hpp"
#include "measure/wall_forces.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

namespace {

// Automatic time step (solver.dt = 0): no body may move more than
// c = solver.max_displacement (default 0.02) times r_min in one step, neither at
// its current speed nor, from rest, under the wall's drive:
//     dt = min(c r_min / v_max, sqrt(2 c r_min / a_wall)).
// Jammed: the wall advanced less than kJamStrain of strain within kJamWindow
// time units (code units R sqrt(rho/tau)); a Newtonian flow at lambda = 0.01
// still shears ~1e-2 in that time.
constexpr double kJamWindow = 50.0;
constexpr double kJamStrain = 1e-4;

double choose_dt(const Config& config, const World& world) {
  if (config.solver.dt > 0.0) return config.solver.dt;
  const Bodies& b = world.bodies;
  double v_max = 0.0, r_min = b.radius[0];
  for (std::size_t i = 0; i < b.size(); ++i) {
    v_max = std::max(v_max, b.velocity[i].norm() + b.radius[i] * b.angular_velocity[i].norm());
    r_min = std::min(r_min, b.radius[i]);
  }
  const SlidingWall& wall = *world.sliding_wall;
  const double c = config.solver.max_displacement;
  const double dt_drive = std::sqrt(2.0 * c * r_min * wall.mass / wall.drive_force);
  return v_max > 0.0 ? std::min(dt_drive, c * r_min / v_max) : dt_drive;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double total_kinetic_energy(const World& world) {
  const SlidingWall& wall = *world.sliding_wall;
  return world.bodies.kinetic_energy() + 0.5 * wall.mass * wall.velocity * wall.velocity;
}

double central_phi(const World& world, double lz) {
  return slab_volume_fraction(world, 0.25 * lz, 0.75 * lz);
}

// Measurements and output schedules at the start of a run.
void start_measurements(const Config& config, ShearCellState& s) {
  const double lz = config.cell->size[2];
  s.profile = VelocityProfile(lz, static_cast<int>(std::ceil(lz)));
  s.next_row_strain = config.run.output_interval;
  s.next_checkpoint_strain = config.run.checkpoint_interval;
  s.next_snapshot_strain = 0.0;
}

ShearCellState initial_state(const Config& config) {
  ShearCellState s;
  s.world = build_shear_cell(config, s.geometry);
  start_measurements(config, s);
  return s;
}

// The state at the end of another run of the same cell, as the start of this
// one: particles, walls, velocities and contact impulses are kept; strain,
// time and every measurement start anew.
ShearCellState continued_state(const Config& config, const std::filesystem::path& checkpoint) {
  ShearCellState previous = load_checkpoint(checkpoint);
  const Vec3& size = config.cell->size;
  if (previous.world.box.length[0] != size[0] || previous.world.box.length[1] != size[1] ||
      previous.world.sliding_wall->spheres.empty())
    throw std::runtime_error(fmt::format("{}: not a state of this cell (cell.size = [{}, {}, {}])",
                                         checkpoint.string(), size[0], size[1], size[2]));
  ShearCellState s;
  s.world = std::move(previous.world);
  s.world.time = 0.0;
  s.geometry = previous.geometry;
  s.dt = previous.dt;
  s.contact_memory = std::move(previous.contact_memory);
  start_measurements(config, s);
  return s;
}

std::vector<std::uint8_t> group_codes(const World& world) {
  std::vector<std::uint8_t> g;
  for (BodyGroup x : world.group) g.push_back(static_cast<std::uint8_t>(x));
  return g;
}

void write_snapshot(const std::filesystem::path& out, ShearCellState& s,
                    const std::vector<Contact>& contacts) {
  const auto k = s.snapshot_strains.size();
  std::filesystem::create_directories(out / "snapshots");
  const auto particles = fmt::format("snapshots/particles_{:04d}.vtp", k);
  const auto network = fmt::format("snapshots/contacts_{:04d}.vtp", k);
  write_particles_vtp(out / particles, s.world, group_codes(s.world));
  write_contacts_vtp(out / network, s.world, contacts, s.dt);
  s.snapshot_strains.push_back(s.strain);
  // The collection's "timestep" is the strain at the snapshot.
  PvdCollection pvd(out / "cell.pvd");
  for (std::size_t n = 0; n < s.snapshot_strains.size(); ++n) {
    pvd.add(s.snapshot_strains[n], fmt::format("snapshots/particles_{:04d}.vtp", n), 0);
    pvd.add(s.snapshot_strains[n], fmt::format("snapshots/contacts_{:04d}.vtp", n), 1);
  }
  pvd.write();
}

void write_series(const std::filesystem::path& out, const ShearCellState& s, double lz) {
  std::string csv = flow_csv_header();
  for (const FlowRow& r : s.rows) csv += flow_csv_row(r, lz);
  write_file_atomically(out / "timeseries.csv", csv);
}

void accumulate_step(const Config& config, ShearCellState& s, const StepReport& report,
                     const std::vector<Contact>& contacts) {
  const CellConfig& cell = *config.cell;
  const double dt = s.dt, area = cell.size[0] * cell.size[1];
  const bool steady = s.strain > config.run.transient_strain;
  const ContactCounts n =
      count_contacts(s.world, contacts, dt, config.friction.s_lim, steady ? &s.histogram : nullptr);
  const WallForces f = wall_forces(s.world, contacts, dt);
  IntervalSums& a = s.interval;
  a.time += dt;
  a.velocity += s.world.sliding_wall->velocity * dt;
  a.kinetic_energy += report.kinetic_energy * dt;
  a.contacts += double(report.contacts_closed) * dt;
  // Contact fractions are time averages: with the adaptive step, a plain count
  // per step would over-weight the fast (short-step) phases of the flow.
  a.closed += n.closed * dt;
  a.boundary += n.boundary * dt;
  a.over_s_lim += n.over_s_lim * dt;
  a.impulsive += n.impulsive * dt;
  a.impulsive_boundary += n.impulsive_boundary * dt;
  a.normal_stress += 0.5 * (f.top[2] - f.bottom[2]) / area * dt;
  a.bottom_force_x += f.bottom[0] * dt;
  a.top_force_z += f.top[2] * dt;
  a.bottom_force_z += f.bottom[2] * dt;
  a.sliding_bl += n.sliding_power_bl * dt;
  a.sliding_hd += n.sliding_power_hd * dt;
  a.work_normal += report.contact_work.normal;
  a.work_bl += report.contact_work.tangential_bl;
  a.work_hd += report.contact_work.tangential_hd;
  a.iterations += report.solve.iterations;
  a.max_residual = std::max(a.max_residual, report.solve.residual);
  a.steps += 1.0;
  a.unconverged += report.solve.converged ? 0.0 : 1.0;
  a.max_overlap = std::max(a.max_overlap, report.max_overlap);
  if (steady) s.profile.add(s.world, dt);
}

void show_progress(const Config& config, const ShearCellState& s, double elapsed) {
  const double lz = config.cell->size[2];
  const CellUnits u = cell_units(config);
  // The wall speed over the current output interval, else the last row's.
  const double v = s.interval.time > 0.0 ? s.interval.velocity / s.interval.time
                   : s.rows.empty()      ? s.world.sliding_wall->velocity
                                         : s.rows.back().wall_velocity;
  const double gdot = v / lz;
  const double done = s.strain / config.run.strain;
  const double left = done > 0.0 ? elapsed * (1.0 - done) / done : 0.0;
  std::cerr << fmt::format(
                   "\rstrain {:6.2f}/{:.2f}  gamma_dot {:9.3g}  eta {:9.3g}  left {:5.0f} s ",
                   s.strain, config.run.strain, gdot / u.rate_unit,
                   gdot > 0.0 ? config.cell->shear_stress / gdot / u.eta_f : 0.0, left)
            << std::flush;
}

}  // namespace

CellOutcome run_shear_cell(const Config& config, const CellRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto& out = options.run.out_dir;
  const CellConfig& cell = *config.cell;
  const double lz = cell.size[2];
  const auto checkpoint = out / "checkpoint.bin";
  std::filesystem::create_directories(out);

  const bool resuming = options.resume && std::filesystem::exists(checkpoint);
  ShearCellState s = resuming                      ? load_checkpoint(checkpoint)
                     : !options.start_from.empty() ? continued_state(config, options.start_from)
                                                   : initial_state(config);
  RunCost cost;
  cost.build_s = seconds_since(start);
  const double strain_at_start = s.strain;
  CellOutcome outcome;
  if (options.resume && (s.strain >= config.run.strain || s.jammed)) {
    // Nothing left to run: keep the finished run's files as they are.
    outcome.steps = s.steps;
    outcome.jammed = s.jammed;
    return outcome;
  }
  write_file_atomically(out / "config.toml", resolved_toml(config));
  const CellUnits units = cell_units(config);
  const SolverSettings settings = make_solver_settings(config.solver);
  cost.threads = settings.threads;
  TimeStepper stepper(make_friction_law(config.friction, units.eta_f), settings,
                      s.dt > 0.0 ? s.dt : 1.0);
  stepper.set_wall_law(CoulombLaw{cell.wall_friction, units.eta_f});
  stepper.restore_contact_memory(s.contact_memory);

  const bool progress = !options.run.quiet && isatty(STDERR_FILENO);
  const auto report_fraction = [&] {
    if (options.progress != nullptr)
      options.progress->store(std::min(1.0, s.strain / std::max(config.run.strain, 1e-300)));
  };
  report_fraction();
  auto last_progress = std::chrono::steady_clock::now();
  while (s.strain < config.run.strain && !s.jammed) {
    s.dt = choose_dt(config, s.world);
    stepper.set_dt(s.dt);
    const SlidingWall& wall = *s.world.sliding_wall;
    if (s.interval.steps == 0.0) s.interval.kinetic_start = total_kinetic_energy(s.world);
    // Work of the drive over the prediction, F dt (V + V_free)/2: exactly the
    // wall's kinetic-energy gain before the contacts act.
    const double drive_work =
        wall.drive_force * s.dt * (wall.velocity + 0.5 * s.dt * wall.drive_force / wall.mass);
    const StepReport report = stepper.step(s.world);
    cost.detection_s += report.detection_seconds;
    cost.solve_s += report.solve_seconds;
    cost.contact_updates += double(report.solve.iterations) * double(report.contacts_detected);
    cost.steps += 1.0;
    ++s.steps;
    s.strain += s.world.sliding_wall->velocity * s.dt / lz;
    const auto measure_start = std::chrono::steady_clock::now();
    accumulate_step(config, s, report, stepper.contacts());
    s.interval.work_drive += drive_work;
    s.interval.kinetic_end = total_kinetic_energy(s.world);

    if (s.strain >= s.next_row_strain) {
      s.rows.push_back(s.interval.close(s.world.time, s.strain));
      s.rows.back().phi_bulk = central_phi(s.world, lz);
      s.interval = IntervalSums{};
      s.next_row_strain += config.run.output_interval;
    }
    if (config.run.snapshot_interval > 0.0 && s.strain >= s.next_snapshot_strain) {
      write_snapshot(out, s, stepper.contacts());
      s.next_snapshot_strain += config.run.snapshot_interval;
    }
    if (s.world.time - s.jam_window_time >= kJamWindow) {
      s.jammed = s.strain - s.jam_window_strain < kJamStrain;
      s.jam_window_time = s.world.time;
      s.jam_window_strain = s.strain;
    }
    cost.measure_s += seconds_since(measure_start);
    report_fraction();
    const bool stop = options.stop_requested != nullptr && options.stop_requested->load();
    if (s.strain >= s.next_checkpoint_strain || stop) {
      s.contact_memory = stepper.contact_memory();
      save_checkpoint(checkpoint, s);
      write_series(out, s, lz);
      while (s.next_checkpoint_strain <= s.strain)
        s.next_checkpoint_strain += config.run.checkpoint_interval;
    }
    if (stop) {
      if (progress) std::cerr << "\n";
      outcome.interrupted = true;
      return outcome;
    }
    if (progress &&
        std::chrono::steady_clock::now() - last_progress > std::chrono::milliseconds(500)) {
      show_progress(
          config, s,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      last_progress = std::chrono::steady_clock::now();
    }
  }
  if (progress) std::cerr << "\n";
  if (s.interval.steps > 0) {
    s.rows.push_back(s.interval.close(s.world.time, s.strain));
    s.interval = IntervalSums{};
  }
  s.contact_memory = stepper.contact_memory();
  save_checkpoint(checkpoint, s);
  write_series(out, s, lz);
  write_file_atomically(out / "velocity_profile.csv", s.profile.csv());
  write_file_atomically(out / "sommerfeld_hist.csv", sommerfeld_histogram_csv(s.histogram));
  write_file_atomically(out / "contacts.csv",
                        contacts_csv(s.world.bodies, stepper.contacts(), s.dt));
  cost.strain = s.strain - strain_at_start;
  cost.wall_s = seconds_since(start);
  write_file_atomically(out / "summary.json", cell_summary(config, s, cost).dump(2) + "\n");
  outcome.steps = s.steps;
  for (const FlowRow& r : s.rows)
    outcome.unconverged_steps += static_cast<long>(r.unconverged_steps);
  outcome.jammed = s.jammed;
  return outcome;
}

}  // namespace dilatant
