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
#include <string>
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
  static ShearCell resumed(Config config, const std::filesystem::path& checkpoint);
  // Continuation along a flow curve (a rheometer's ramp): the final state of
  // another run of the same cell (particles, walls, velocities, contact
  // impulses); strain, time and every measurement start at zero, and the
  // friction law and drive are this config's. Throws if the cell differs.
  static ShearCell continued(Config config, const std::filesystem::path& checkpoint);

  // One time step and its measurements.
  const StepReport& step();
  // run.strain reached, or jammed: the wall advanced less than kJamStrain
  // within kJamWindow time units (code units R sqrt(rho_p/tau); a Newtonian
  // flow at lambda = 0.01 still shears ~1e-2 in that time).
  bool done() const { return state_.strain >= config_.run.strain || state_.jammed; }
  double fraction_done() const;
  // Closes the time series' last, partial interval (at the end of a run).
  void finish();

  // Output schedules (in strain), met by the caller's run loop.
  bool snapshot_due() const;
  bool checkpoint_due() const { return state_.strain >= state_.next_checkpoint_strain; }

  // Writers: every file atomically (write, then rename).
  void write_checkpoint(const std::filesystem::path& file);       // and moves its schedule on
  void write_snapshot(const std::filesystem::path& out_dir);      // snapshots/*.vtp + cell.pvd
  void write_series(const std::filesystem::path& out_dir) const;  // timeseries.csv
  // The end-of-run files: timeseries.csv, velocity_profile.csv,
  // sommerfeld_hist.csv, contacts.csv, summary.json.
  void write_results(const std::filesystem::path& out_dir, const RunCost& cost) const;

  // The progress line of a terminal: strain, shear rate, viscosity, time left.
  std::string progress_line(double elapsed_seconds) const;

  const Config& config() const { return config_; }
  const ShearCellState& state() const { return state_; }
  const CellUnits& units() const { return units_; }
  const std::vector<Contact>& contacts() const { return stepper_.contacts(); }
  // Time spent so far in detection, solve and measurement, and the work done.
  const RunCost& cost() const { return cost_; }

  // The largest overlap a sound run leaves, as a fraction of the smallest
  // radius (docs/model.md "Overlaps"): linearising the gap over one step
  // gives (0.02 r)^2 / r = 4e-4 r, unconverged solves more; beyond 1% a run
  // is warned about and its summary says overlap_exceeded.
  static constexpr double kOverlapTolerance = 0.01;
  static constexpr double kJamWindow = 50.0;
  static constexpr double kJamStrain = 1e-4;

 private:
  ShearCell(Config config, ShearCellState state);
  // The automatic step, and whether the drive's bound (not the speed of the
  // fastest body) set it.
  struct StepChoice {
    double dt = 0.0;
    bool by_drive = false;
    double dt_drive = 0.0;  // the drive's bound alone (0 with a fixed solver.dt)
    // Fastest push-out of an overlap, c r_min / dt_drive (choose_dt(); none with
    // a fixed solver.dt, whose step no speed can shorten).
    double max_push_out = kNoPushOutCap;
  };
  // A body a million times faster than the drive can make the wall in one step
  // (the automatic step collapsed by that factor): a numerical blow-up.
  static constexpr double kCollapsedStep = 1e-6;
  StepChoice choose_dt() const;
  double total_kinetic_energy() const;
  // The step's measurements with the drive's speed it ran at; returns its
  // particle shear stress sigma_zx (the drive responds to it).
  double accumulate(const StepReport& report, double velocity);
  void close_row();

  Config config_;
  CellUnits units_;
  ShearCellState state_;
  std::unique_ptr<SuspendingFluid> fluid_;  // null: the literal model
  TimeStepper stepper_;
  StepReport last_;
  RunCost cost_;
};

}  // namespace dilatant
