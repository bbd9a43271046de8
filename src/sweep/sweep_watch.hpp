#pragma once
// The watching side of a running sweep, in the process that keeps the table
// (the local sweep, or rank 0 of an MPI sweep): after each wait for events it
// rewrites flowcurves.csv when a point finished, prints the notes (failed
// points) and, once a second on a terminal, the progress line
//
//   sweep: 3/12 done, 2 running, 1 failed; 1m05s elapsed, about 4m left
//
// and turns an external stop (SIGINT) into the sweep's halt. Whether or not a
// terminal shows that line, DIR/progress.txt holds it, with each running
// point's share of its run, rewritten every 10 s (atomically) and once at the
// end: a sweep left running under nohup or a batch system can be followed
// with `cat DIR/progress.txt`.
//
//   # dilatant sweep: progress at 2026-11-29T01:02:03Z (rewritten every 10 s)
//   sweep: 16/22 done, 2 running, 0 failed; 1h05m elapsed, about 8h10m left
//   running: points/008-seed=1_lambda=1000 38%
//   running: points/019-seed=2_lambda=1000 35%
#include <chrono>
#include <vector>

#include "sweep/sweep_work.hpp"

namespace dilatant::sweep {

class SweepWatch {
 public:
  SweepWatch(SweepWork& work, const SweepRunOptions& options);
  void tick(const SweepEvents& events);
  // Ends the progress line (a newline) when one was drawn.
  void finish();

 private:
  std::string progress_line();
  double fraction_done() const;
  // DIR/progress.txt; `ended` after the last worker stopped.
  void write_progress_file(bool ended);

  using Clock = std::chrono::steady_clock;
  SweepWork& work_;
  const SweepRunOptions& options_;
  std::vector<double> baseline_;  // each point's fraction when this invocation took it up
  Clock::time_point start_;
  Clock::time_point last_line_;
  Clock::time_point last_file_;
  bool progress_shown_ = false;
  bool progress_file_failed_ = false;
};

}  // namespace dilatant::sweep
