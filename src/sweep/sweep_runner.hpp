#pragma once
// Runs the points of a sweep side by side and keeps its folder up to date:
//
//   DIR/sweep.toml           the resolved sweep (sweep_plan.hpp)
//   DIR/flowcurves.csv       one row per point (flow_table.hpp), rewritten
//                            atomically whenever a point finishes
//   DIR/progress.txt         the progress line and the running points'
//                            shares, every 10 s (sweep_watch.hpp)
//   DIR/points/NNN-label/    each point's run folder (as `dilatant run` writes),
//                            plus error.txt when the point failed
//
// Work is shared by `jobs` worker threads, one point (or, with continuation,
// one flow curve: its points in order of lambda) at a time, each run with its
// own solver.threads (1 by default). A point that throws is recorded as failed
// with its message and the others go on; a continued point whose predecessor
// failed fails too ("not run: ..."); one above its ramp's jam is skipped and a
// continued point that jams gets a cold start (sweep_plan.hpp, "A ramp that
// jams"). Re-running resumes (point_folder.hpp):
// finished points are skipped, interrupted ones continue from their
// checkpoint, failed and pending ones run again.
//
// When *stop becomes true (SIGINT), running points write a checkpoint and stop,
// no new point starts, and the table is written: re-running resumes.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <string>

#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep {

struct SweepRunOptions {
  std::filesystem::path out;
  int jobs = 1;                  // worker threads, >= 1
  bool show_progress = false;    // a status line on stderr, redrawn each second
  bool report_failures = false;  // a line on stderr per failed point
  const std::atomic<bool>* stop = nullptr;
  // When set: the fraction of the sweep done (a finished, failed or skipped
  // point counts 1, a running one its fraction of run.strain), updated by the
  // watching thread (sweep_watch.hpp) about ten times a second.
  std::atomic<double>* progress = nullptr;
};

struct SweepOutcome {
  std::size_t points = 0;
  std::size_t done = 0;     // finished, in this invocation or before
  std::size_t skipped = 0;  // of those, finished before this invocation
  std::size_t failed = 0;
  std::size_t pending = 0;    // not run (interrupted)
  std::size_t above_jam = 0;  // not run: above the jam of their ramp
  bool interrupted = false;
  // Done points with steps that ended at solver.max_iterations, and the one
  // with the largest share of them (frac_steps_unconverged).
  std::size_t unconverged_points = 0;
  double most_unconverged = 0.0;
  std::string most_unconverged_point;
};

// Throws InputError, before running anything, when a point's folder holds a
// run of another configuration.
SweepOutcome run_sweep(const SweepPlan& plan, const SweepRunOptions& options);

}  // namespace dilatant::sweep
