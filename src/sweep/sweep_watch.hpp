#pragma once
// The watching side of a running sweep, in the process that keeps the table
// (the local sweep, or rank 0 of an MPI sweep): after each wait for events it
// rewrites flowcurves.csv when a point finished, prints the notes (failed
// points) and, once a second on a terminal, the progress line
//
//   sweep: 3/12 done, 2 running, 1 failed; 1m05s elapsed, about 4m left
//
// and turns an external stop (SIGINT) into the sweep's halt.
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

  using Clock = std::chrono::steady_clock;
  SweepWork& work_;
  const SweepRunOptions& options_;
  std::vector<double> baseline_;  // each point's fraction when this invocation took it up
  Clock::time_point start_;
  Clock::time_point last_line_;
  bool progress_shown_ = false;
};

}  // namespace dilatant::sweep
