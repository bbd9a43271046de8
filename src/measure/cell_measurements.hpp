#pragma once
// Everything a shear cell measures as it runs, in one owner: the running sums
// of the current output interval, the time series' rows, the velocity profile
// and the Sommerfeld histogram. The cell hands each step over (accumulate),
// closes a row when its schedule says so, and at the end asks for the typed
// records the summary is written from (measure/rheology.hpp,
// measure/cell_records.hpp). The drive (boundary/drive.hpp) answers the
// questions that depend on what shears the cell: the forces on its
// walls, its mean flow and its normal stress.
//
// It is part of the checkpoint (drivers/shear_cell_state.cpp writes its
// members in the format's order), so a resumed run continues its averages.
#include <vector>

#include "boundary/drive.hpp"
#include "detection/contact.hpp"
#include "measure/cell_records.hpp"
#include "measure/cell_units.hpp"
#include "measure/contact_statistics.hpp"
#include "measure/flow_series.hpp"
#include "measure/rheology.hpp"
#include "measure/velocity_profile.hpp"
#include "solver/time_stepper.hpp"
#include "world/world.hpp"

namespace dilatant {

// One step as the measurements see it, after the drive's speed is known.
struct StepSample {
  const World& world;
  const Drive& drive;
  const std::vector<Contact>& contacts;  // the step's, with their impulses
  const StepReport& report;
  double dt = 0.0;
  double velocity = 0.0;  // the drive's speed the step ran at
  double strain = 0.0;    // at the step's end
  long step = 0;          // its number (1 for the first)
};

// What the cell's configuration fixes for its measurements.
struct MeasurementSettings {
  double volume = 0.0;            // Lx Ly Lz: the stress is averaged over it (the box's now)
  double s_lim = 0.0;             // friction.s_lim, for the fraction beyond it
  double transient_strain = 0.0;  // profile and histogram only past it
};

// Every steady-state record of a run (summary.json), past `from` (strain).
struct CellRecords {
  Rheology rheology;
  StressRecord stress;
  ContactRecord contacts;
  EnergyRecord energy;
  WallForceRecord wall_forces;
  SolverRecord solver;
};

class CellMeasurements {
 public:
  CellMeasurements() = default;
  // A profile of `bins` layers over the height `lz` (one per radius in the cell).
  CellMeasurements(double lz, int bins) : profile(lz, bins) {}

  // Before a step: the total kinetic energy (particles and drive) the
  // interval starts from, if this step opens it.
  void begin_step(double kinetic_energy) {
    if (interval.steps == 0.0) interval.kinetic_start = kinetic_energy;
  }
  // Adds one step; returns its particle stresses sigma_zx and sigma_zz (code
  // units), to which the drive responds.
  StepStress accumulate(const StepSample& step, const MeasurementSettings& settings);
  // After the drive's response: the work it fed in the step and the total
  // kinetic energy the step ends with.
  void end_step(double drive_work, double kinetic_energy) {
    interval.work_drive += drive_work;
    interval.kinetic_end = kinetic_energy;
  }
  // Closes the current interval into a row that ends at (time, strain), with
  // the bulk fraction of the state that ends it.
  void close_row(double time, double strain, double phi_bulk);
  bool interval_open() const { return interval.steps > 0.0; }
  // The drive's speed over the current interval, else the last row's (a
  // progress line's), else `current`.
  double recent_speed(double current) const;

  CellRecords records(double from, const ShearGeometry& geometry, const CellUnits& units,
                      bool walls) const;

  // Empties the averages kept past the transient only (profile, histogram):
  // a run resumed with a transient moved beyond the strain it had reached
  // averages them from there, like the rows it averages past `from`.
  void restart_steady_averages();

  IntervalSums interval;
  std::vector<FlowRow> rows;
  VelocityProfile profile;
  SommerfeldHistogram histogram;
};

}  // namespace dilatant
