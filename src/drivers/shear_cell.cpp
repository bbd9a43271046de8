#include "drivers/shear_cell.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "drivers/model_setup.hpp"
#include "drivers/shear_cell_summary.hpp"
#include "measure/particle_stress.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

namespace {

CellUnits units_of(const Config& config) {
  return make_cell_units(config.cell()->shear_stress, config.density, config.cell()->radius_max,
                         config.fluid.lambda);
}

// Measurements and output schedules at the start of a run.
void start_measurements(const Config& config, ShearCellState& s) {
  const double lz = config.cell()->size[2];
  s.profile = VelocityProfile(lz, static_cast<int>(std::ceil(lz)));
  s.next_row_strain = config.run.output_interval;
  s.next_checkpoint_strain = config.run.checkpoint_interval;
  s.next_snapshot_strain = 0.0;
}

ShearCellState new_state(const Config& config) {
  ShearCellState s;
  s.world = build_cell(config, s.geometry, s.drive);
  start_measurements(config, s);
  return s;
}

}  // namespace

ShearCell::ShearCell(Config config) : ShearCell(config, new_state(config)) {}

ShearCell::ShearCell(Config config, ShearCellState state)
    : config_(std::move(config)),
      units_(units_of(config_)),
      state_(std::move(state)),
      fluid_(make_fluid(config_.fluid, units_.eta_f)),
      stepper_(make_friction_law(config_.friction, units_.eta_f),
               make_solver_settings(config_.solver), state_.dt > 0.0 ? state_.dt : 1.0) {
  // The walls are rough glued grains: Coulomb friction (docs/shear-cell.md).
  state_.drive->set_contact_law(CoulombLaw{config_.cell()->wall_friction, units_.eta_f});
  stepper_.restore_contact_memory(state_.contact_memory);
  stepper_.set_fluid_forces(fluid_.get());
  cost_.threads = stepper_.settings().threads;
}

ShearCell ShearCell::resumed(Config config, const std::filesystem::path& checkpoint) {
  ShearCellState state = load_checkpoint(checkpoint);
  return ShearCell(std::move(config), std::move(state));
}

ShearCell ShearCell::continued(Config config, const std::filesystem::path& checkpoint) {
  ShearCellState previous = load_checkpoint(checkpoint);
  const CellConfig& cell = *config.cell();
  const Vec3& size = cell.size;
  // The same drive too, which takes this config's control (Drive::adopt): a
  // wall cell's state cannot continue without walls, nor a Lees–Edwards state
  // with them.
  if (previous.world.box.length[0] != size[0] || previous.world.box.length[1] != size[1] ||
      !previous.drive->adopt(drive_spec(config), previous.world))
    throw std::runtime_error(fmt::format(
        "{}: not a state of this cell (cell.size = [{}, {}, {}], cell.boundary = \"{}\")",
        checkpoint.string(), size[0], size[1], size[2],
        cell.boundary == CellBoundary::LeesEdwards ? "lees-edwards" : "walls"));
  ShearCellState s;
  s.world = std::move(previous.world);
  s.world.time = 0.0;
  s.drive = std::move(previous.drive);
  s.geometry = previous.geometry;
  s.dt = previous.dt;
  s.contact_memory = std::move(previous.contact_memory);
  start_measurements(config, s);
  return ShearCell(std::move(config), std::move(s));
}

// Automatic time step (solver.dt = 0): no body may move more than
// c = solver.max_displacement (default 0.02) times r_min in one step, neither at
// its current speed nor under the drive (its own bound, Drive::time_step_bound;
// from rest under a force, sqrt(2 c r_min / a)):
//     dt = min(c r_min / v_max, dt_drive).
// An overlap left by an unconverged step is pushed out at |g|/dt, so a shorter
// step pushes it faster; the fastest body sets the next step, so past a point
// speed and step feed each other until the run blows up (a cold start at
// phi 0.64 did: docs/model.md "Overlap push-out"). The solver therefore pushes
// overlaps out no faster than c r_min / dt_drive: a push-out alone never asks
// for a step shorter than the drive's, whatever the step.
ShearCell::StepChoice ShearCell::choose_dt() const {
  if (config_.solver.dt > 0.0) return {config_.solver.dt, false};
  const Bodies& b = state_.world.bodies;
  double v_max = 0.0, r_min = b.radius[0];
  for (std::size_t i = 0; i < b.size(); ++i) {
    v_max = std::max(v_max, b.velocity[i].norm() + b.radius[i] * b.angular_velocity[i].norm());
    r_min = std::min(r_min, b.radius[i]);
  }
  const double c = config_.solver.max_displacement;
  const double dt_drive = state_.drive->time_step_bound(state_.world, c * r_min);
  const double dt_speed = v_max > 0.0 ? c * r_min / v_max : dt_drive;
  return {std::min(dt_drive, dt_speed), dt_drive <= dt_speed, dt_drive, c * r_min / dt_drive};
}

double ShearCell::total_kinetic_energy() const {
  return state_.world.bodies.kinetic_energy() + state_.drive->kinetic_energy();
}

double ShearCell::fraction_done() const {
  return std::min(1.0, state_.strain / std::max(config_.run.strain, 1e-300));
}

bool ShearCell::snapshot_due() const {
  return config_.run.snapshot_interval > 0.0 && state_.strain >= state_.next_snapshot_strain;
}

const StepReport& ShearCell::step() {
  ShearCellState& s = state_;
  const double lz = config_.cell()->size[2];
  const StepChoice choice = choose_dt();
  // Never a silent bad number: a state that has blown up stops the run (a
  // sweep records the point as failed with this message).
  if (!std::isfinite(choice.dt) || choice.dt < kCollapsedStep * choice.dt_drive ||
      !std::isfinite(s.drive_speed())) {
    throw std::runtime_error(fmt::format(
        "numerical blow-up at step {} (strain {:.4g}): {} speed {:.3g}, time step {:.3g} "
        "against the drive's {:.3g}; the run is stopped",
        s.steps, s.strain, s.drive->mover(), s.drive_speed(), choice.dt, choice.dt_drive));
  }
  s.dt = choice.dt;
  cost_.steps_dt_by_drive += choice.by_drive ? 1.0 : 0.0;
  stepper_.set_dt(s.dt);
  stepper_.set_max_push_out(choice.max_push_out);
  if (s.interval.steps == 0.0) s.interval.kinetic_start = total_kinetic_energy();
  // The drag is relative to the drive's mean flow at the step's start
  // (fluid/stokes_drag.hpp): the profile a steady flow has, so that the fluid
  // neither drives nor brakes it.
  if (fluid_) fluid_->set_ambient(s.drive->mean_flow(s.world));
  try {
    last_ = stepper_.step(s.world, s.drive->contact_block());
  } catch (const NumericalFault& fault) {
    throw NumericalFault(fmt::format("step {} (strain {:.4g}): {}; the run is stopped", s.steps + 1,
                                     s.strain, fault.what()));
  }
  cost_.detection_s += last_.detection_seconds;
  cost_.solve_s += last_.solve_seconds;
  cost_.contact_updates += last_.solve.contact_visits;
  if (last_.contacts_detected > 0)
    cost_.sweep_equivalents += last_.solve.contact_visits / double(last_.contacts_detected);
  cost_.steps += 1.0;
  ++s.steps;
  // The speed the strain advances with: the wall's at the step's end, or the
  // images' of the step (constant within it; respond() changes it below).
  const double velocity = s.drive_speed();
  s.strain += velocity * s.dt / lz;

  const auto measure_start = std::chrono::steady_clock::now();
  const double sigma_zx = accumulate(last_, velocity);
  s.interval.work_drive += s.drive->fed_work(s.world, sigma_zx, s.dt);
  // The drive's answer to the step's stress (under the images' stress control:
  // the next step's speed).
  s.drive->respond(s.world, sigma_zx, s.dt);
  s.interval.kinetic_end = total_kinetic_energy();
  if (s.strain >= s.next_row_strain) {
    close_row();
    s.next_row_strain += config_.run.output_interval;
  }
  if (s.world.time - s.jam_window_time >= kJamWindow) {
    s.jammed = s.strain - s.jam_window_strain < kJamStrain;
    s.jam_window_time = s.world.time;
    s.jam_window_strain = s.strain;
  }
  cost_.measure_s += seconds_since(measure_start);
  return last_;
}

double ShearCell::accumulate(const StepReport& report, double velocity) {
  ShearCellState& s = state_;
  const CellConfig& cell = *config_.cell();
  const std::vector<Contact>& contacts = stepper_.contacts();
  const double dt = s.dt, area = cell.size[0] * cell.size[1];
  const bool steady = s.strain > config_.run.transient_strain;
  const Drive& drive = *s.drive;
  const ContactCounts n = count_contacts(s.world.bodies, contacts, dt, config_.friction.s_lim,
                                         steady ? &s.histogram : nullptr);
  const WallForces f = drive.wall_forces(s.world, contacts, dt);
  IntervalSums& a = s.interval;
  a.time += dt;
  a.velocity += velocity * dt;
  a.kinetic_energy += report.kinetic_energy * dt;
  a.contacts += double(report.contacts_closed) * dt;
  // Contact fractions are time averages: with the adaptive step, a plain count
  // per step would over-weight the fast (short-step) phases of the flow.
  a.closed += n.closed * dt;
  a.boundary += n.boundary * dt;
  a.over_s_lim += n.over_s_lim * dt;
  a.impulsive += n.impulsive * dt;
  a.impulsive_boundary += n.impulsive_boundary * dt;
  a.bottom_force_x += f.bottom[0] * dt;
  a.top_force_z += f.top[2] * dt;
  a.bottom_force_z += f.bottom[2] * dt;
  a.sliding_bl += n.sliding_power_bl * dt;
  a.sliding_hd += n.sliding_power_hd * dt;
  a.work_normal += report.contact_work.normal;
  a.work_bl += report.contact_work.tangential_bl;
  a.work_hd += report.contact_work.tangential_hd;
  a.work_lubrication += report.contact_work.lubrication;
  a.work_drag += report.drag_work;
  a.iterations += report.solve.iterations;
  a.max_residual = std::max(a.max_residual, report.solve.residual);
  const ContactResidual& r = report.contact_residual;
  const auto body_ids = [&](const Contact& c) {  // a plane k as -(k+1), as contacts.csv
    const Bodies& b = s.world.bodies;
    return std::pair{
        double(b.id[static_cast<std::size_t>(c.i)]),
        c.with_plane() ? double(c.other) : double(b.id[static_cast<std::size_t>(c.other)])};
  };
  if (r.max() > a.contact_residual_max && r.worst_contact >= 0) {
    a.contact_residual_step = double(s.steps);
    std::tie(a.contact_residual_body_i, a.contact_residual_body_j) =
        body_ids(contacts[static_cast<std::size_t>(r.worst_contact)]);
  }
  a.contact_residual_max = std::max(a.contact_residual_max, r.max());
  a.contact_residual_rms += std::hypot(r.normal_rms, r.tangential_rms);
  a.steps += 1.0;
  a.unconverged += report.solve.converged ? 0.0 : 1.0;
  if (report.max_overlap > a.max_overlap && report.max_overlap_contact >= 0) {
    a.max_overlap = report.max_overlap;
    a.max_overlap_step = double(s.steps);
    std::tie(a.max_overlap_body_i, a.max_overlap_body_j) =
        body_ids(contacts[static_cast<std::size_t>(report.max_overlap_contact)]);
  }
  // Particle stress over the volume between the walls' centre planes, z = 0 to
  // Lz (measure/particle_stress.hpp: there its sigma_zx averages to tau), or
  // over the Lees–Edwards box; the mean flow is the one the drag also uses.
  const Tensor3 virial = contact_impulse_moment(contacts);
  const Tensor3 kinetic = velocity_fluctuation_moment(s.world.bodies, drive.mean_flow(s.world));
  const double volume = area * cell.size[2];
  Tensor3 sigma;
  for (std::size_t k = 0; k < virial.size(); ++k) {
    a.stress_dt[k] -= (virial[k] + kinetic[k] * dt) / volume;
    sigma[k] = -(virial[k] + kinetic[k] * dt) / (volume * dt);
  }
  // On the walls, or without them the bulk's (Drive::normal_stress).
  a.normal_stress += drive.normal_stress(s.world, f, sigma[tensor_index(kZ, kZ)]) * dt;
  if (steady) s.profile.add(s.world, dt);
  return sigma[tensor_index(kZ, kX)];
}

// A row of the time series from the interval's sums, with the bulk fraction
// of the state that ends it.
void ShearCell::close_row() {
  ShearCellState& s = state_;
  s.rows.push_back(s.interval.close(s.world.time, s.strain));
  s.rows.back().phi_bulk = bulk_fraction(s);
  s.interval = IntervalSums{};
}

void ShearCell::finish() {
  // The last, partial row (a jam's waiting time can make it long: without its
  // bulk fraction it would pull the duration-weighted phi_bulk towards 0).
  if (state_.interval.steps > 0) close_row();
}

}  // namespace dilatant
