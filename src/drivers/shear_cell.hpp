#pragma once
// The paper's shear cell as an object (docs/model.md "Shear cell"): build it,
// step it, read its state and measurements, write its outputs. The CLI's run
// loop (drivers/shear_cell_run.hpp), the sweeps and the tests all drive this
// one object; it is what a script holds while a cell runs.
//
//     ShearCell cell(config);                 // walls + packing from cell.seed
//     while (!cell.done()) cell.step();       // to run.strain, or until it jams
//     cell.finish();                          // close the last time-series row
//     cell.write_results(out, cost);          // summary.json, profiles, contacts ...
//
// Units: code units R = rho_p = tau = 1 inside (measure/cell_units.hpp); the
// summary reports the paper's units.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "drivers/shear_cell_state.hpp"
#include "fluid/suspending_fluid.hpp"
#include "io/config.hpp"
#include "measure/cell_units.hpp"
#include "measure/particle_stress.hpp"
#include "measure/run_cost.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

class ShearCell {
 public:
  // A new cell: rough walls and a packing at cell.phi, reproducibly from cell.seed.
  explicit ShearCell(Config config);
  // Exactly where an interrupted run of this config stopped (its checkpoint).
  // With `transient_moved` (the run is resumed with a run.transient_strain
  // beyond every strain it had reached), the velocity profile and Sommerfeld
  // histogram, which average past the transient, start anew.
  static ShearCell resumed(Config config, const std::filesystem::path& checkpoint,
                           bool transient_moved = false);
  // Continuation along a flow curve (a rheometer's ramp): the final state of
  // another run of the same cell (particles, walls, velocities, contact
  // impulses); strain, time and every measurement start at zero, and the
  // friction law and drive are this config's. Throws if the cell differs.
  static ShearCell continued(Config config, const std::filesystem::path& checkpoint);

  // One time step and its measurements.
  const StepReport& step();
  // run.strain reached, or jammed (measure/jam_watch.hpp).
  bool done() const { return state_.strain >= config_.run.strain || state_.jam.jammed; }
  double fraction_done() const;
  // Closes the time series' last, partial interval (at the end of a run).
  void finish();

  // Output schedules (in strain, drivers/strain_schedule.hpp), met by the
  // caller's run loop; each writer moves its schedule on.
  bool snapshot_due() const { return state_.schedules.snapshots.due(state_.strain); }
  bool checkpoint_due() const { return state_.schedules.checkpoints.due(state_.strain); }

  // Writers: every file atomically (write, then rename).
  void write_checkpoint(const std::filesystem::path& file);
  // The bytes write_checkpoint would write now, the schedule left as it is
  // (a step's state kept in memory: drivers/step_dumps.hpp).
  std::string checkpoint_bytes();
  void write_snapshot(const std::filesystem::path& out_dir);      // snapshots/*.vtp + cell.pvd
  void write_series(const std::filesystem::path& out_dir) const;  // timeseries.csv
  // The end-of-run files: timeseries.csv, velocity_profile.csv,
  // sommerfeld_hist.csv, contacts.csv, summary.json; returns the summary it
  // wrote (a sweep's table is filled from it, not from the file read back).
  nlohmann::json write_results(const std::filesystem::path& out_dir, const RunCost& cost) const;

  // The progress line of a terminal: strain, shear rate, viscosity, time left.
  std::string progress_line(double elapsed_seconds) const;

  const Config& config() const { return config_; }
  const ShearCellState& state() const { return state_; }
  const CellUnits& units() const { return units_; }
  const std::vector<Contact>& contacts() const { return stepper_.contacts(); }
  // Called after every pass of each step's solve (solver/contact_problem.hpp):
  // a tool's view of a method's work against its residual; empty: none.
  void set_pass_observer(PassObserver observer) { stepper_.set_pass_observer(std::move(observer)); }
  // Time spent so far in detection, solve and measurement, and the work done.
  const RunCost& cost() const { return cost_; }

  // The largest overlap a sound run leaves, as a fraction of the smallest
  // radius (docs/model.md "Overlaps"): linearising the gap over one step
  // gives (0.02 r)^2 / r = 4e-4 r, unconverged solves more; beyond 1% a run
  // is warned about and its summary says overlap_exceeded.
  static constexpr double kOverlapTolerance = 0.01;

 private:
  ShearCell(Config config, ShearCellState state);
  // A body a million times faster than the drive can make the wall in one step
  // (the automatic step collapsed by that factor): a numerical blow-up.
  static constexpr double kCollapsedStep = 1e-6;
  double total_kinetic_energy() const;
  void close_row();
  // A fault of the stepper's, with the step and strain it stopped at.
  std::string where_stopped(const std::exception& fault) const;

  Config config_;
  CellUnits units_;
  MeasurementSettings measurement_settings_;
  ShearCellState state_;
  std::unique_ptr<SuspendingFluid> fluid_;  // null: the literal model
  TimeStepper stepper_;
  StepReport last_;
  RunCost cost_;
};

}  // namespace dilatant
