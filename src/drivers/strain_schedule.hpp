#pragma once
// When a shear cell does something periodic in strain: close a row of the
// time series, write a ParaView snapshot, write a checkpoint. Each is one
// schedule object the run loop asks "due?" and moves on after acting, so the
// cell keeps no next_*_strain bookkeeping of its own. Only `next` is part of
// the checkpoint: the interval is the run's setting (run.output_interval,
// run.snapshot_interval, run.checkpoint_interval).
namespace dilatant {

struct StrainSchedule {
  double interval = 0.0;  // in strain; 0 never comes due (snapshots switched off)
  double next = 0.0;      // the strain at which it is next due

  bool due(double strain) const { return interval > 0.0 && strain >= next; }
  // After acting on it: the next time, one interval on (a row or a snapshot
  // closes at most once per step, so the next one keeps its place on the grid).
  void advance() { next += interval; }
  // The first grid point past `strain` (a checkpoint written early, on a stop
  // request, must not make the next ones come due in a burst).
  void advance_past(double strain) {
    while (interval > 0.0 && next <= strain) next += interval;
  }
};

// The three schedules of a shear cell.
struct CellSchedules {
  StrainSchedule rows, snapshots, checkpoints;
};

}  // namespace dilatant
