#include "drivers/shear_cell.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "drivers/cell_time_step.hpp"
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

// Measurements and output schedules at the start of a run: a row, a
// checkpoint one interval on, a snapshot of the initial state.
void start_measurements(const Config& config, ShearCellState& s) {
  const double lz = config.cell()->size[2];
  s.measurements = CellMeasurements(lz, static_cast<int>(std::ceil(lz)));
  s.schedules.rows.next = config.run.output_interval;
  s.schedules.checkpoints.next = config.run.checkpoint_interval;
  s.schedules.snapshots.next = 0.0;
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
      stepper_(make_friction_law(config_.friction, units_.eta_f, config_.critical_load()),
               make_solver_settings(config_.solver), state_.dt > 0.0 ? state_.dt : 1.0) {
  // The walls are rough glued grains: Coulomb friction (docs/shear-cell.md).
  state_.drive->set_contact_law(CoulombLaw{config_.cell()->wall_friction, units_.eta_f});
  stepper_.restore_contact_memory(state_.contact_memory);
  stepper_.set_fluid_forces(fluid_.get());
  cost_.threads = stepper_.settings().threads;
  // The schedules' intervals are this run's settings; only their next strains
  // come from the state (a checkpoint's).
  state_.schedules.rows.interval = config_.run.output_interval;
  state_.schedules.snapshots.interval = config_.run.snapshot_interval;
  state_.schedules.checkpoints.interval = config_.run.checkpoint_interval;
  const Vec3& size = config_.cell()->size;
  measurement_settings_ = {.volume = size[0] * size[1] * size[2],
                           .s_lim = config_.friction.s_lim,
                           .transient_strain = config_.run.transient_strain};
}

ShearCell ShearCell::resumed(Config config, const std::filesystem::path& checkpoint,
                             bool transient_moved) {
  ShearCellState state = load_checkpoint(checkpoint);
  if (transient_moved) state.measurements.restart_steady_averages();
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

double ShearCell::total_kinetic_energy() const {
  return state_.world.bodies.kinetic_energy() + state_.drive->kinetic_energy();
}

double ShearCell::fraction_done() const {
  return std::min(1.0, state_.strain / std::max(config_.run.strain, 1e-300));
}

std::string ShearCell::where_stopped(const std::exception& fault) const {
  return fmt::format("step {} (strain {:.4g}): {}; the run is stopped", state_.steps + 1,
                     state_.strain, fault.what());
}

const StepReport& ShearCell::step() {
  ShearCellState& s = state_;
  const TimeStepChoice choice = choose_time_step(s.world, *s.drive, config_.solver);
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
  stepper_.set_mean_flow(choice.mean_flow);
  const CellConfig& cell = *config_.cell();
  const double diameter = 2.0 * cell.radius_max;
  stepper_.set_reference_force(
      reference_stress(cell, config_.density, units_.eta_f, s.measurements.rows) * diameter *
      diameter);
  // An unconverged solve is redone at half the step, down to 1/64 of the step
  // chosen; below, the run stops (solver/time_stepper.hpp, docs/model.md
  // "Unconverged steps").
  stepper_.set_shortest_dt(choice.dt / kShortestStepDivisor);
  s.measurements.begin_step(total_kinetic_energy());
  // The drag is relative to the drive's mean flow at the step's start
  // (fluid/stokes_drag.hpp): the profile a steady flow has, so that the fluid
  // neither drives nor brakes it.
  if (fluid_) fluid_->set_ambient(s.drive->mean_flow(s.world));
  try {
    last_ = stepper_.step(s.world, s.drive->contact_block());
  } catch (const SolveFailure& fault) {
    throw SolveFailure(where_stopped(fault));
  } catch (const NumericalFault& fault) {
    throw NumericalFault(where_stopped(fault));
  }
  s.dt = last_.dt;  // shorter than chosen if the step was redone
  cost_.add_step(last_);
  ++s.steps;
  // The speed the strain advances with: the wall's at the step's end, or the
  // images' of the step (constant within it; respond() changes it below).
  // Under pressure control the box height H varies: the cell measures in the
  // height it was built with, H0 (docs/shear-cell.md "The pressure-imposed
  // cell"), the images' speed as V H0 / H (= gamma_dot H0, so that the strain,
  // the rows' shear rate V / H0 and the summary's are gamma_dot's), the
  // stress over the box's current volume.
  const double height = s.world.box.lees_edwards ? s.geometry.gap_height : config_.cell()->size[2];
  const double velocity =
      s.world.box.lees_edwards ? s.drive_speed() * height / s.world.box.length[2] : s.drive_speed();
  s.strain += velocity * s.dt / height;
  if (s.world.box.lees_edwards)
    measurement_settings_.volume =
        s.world.box.length[0] * s.world.box.length[1] * s.world.box.length[2];

  const auto measure_start = std::chrono::steady_clock::now();
  const StepStress stress = s.measurements.accumulate({.world = s.world,
                                                       .drive = *s.drive,
                                                       .contacts = stepper_.contacts(),
                                                       .report = last_,
                                                       .dt = s.dt,
                                                       .velocity = velocity,
                                                       .strain = s.strain,
                                                       .step = s.steps},
                                                      measurement_settings_);
  const double fed = s.drive->fed_work(s.world, stress.sigma_zx, s.dt);
  // The drive's answer to the step's stress (under the images' stress control:
  // the next step's speed; under pressure control: the box's height).
  s.drive->respond(s.world, stress, s.dt);
  s.measurements.end_step(fed, total_kinetic_energy());
  if (s.schedules.rows.due(s.strain)) {
    close_row();
    s.schedules.rows.advance();
  }
  s.jam.observe(s.world.time, s.strain);
  cost_.measure_s += seconds_since(measure_start);
  return last_;
}

// A row of the time series from the interval's sums, with the bulk fraction
// of the state that ends it.
void ShearCell::close_row() {
  state_.measurements.close_row(state_.world.time, state_.strain, bulk_fraction(state_));
}

void ShearCell::finish() {
  // The last, partial row (a jam's waiting time can make it long: without its
  // bulk fraction it would pull the duration-weighted phi_bulk towards 0).
  if (state_.measurements.interval_open()) close_row();
}

}  // namespace dilatant
