#pragma once
// Runs a scene to run.time and writes its results folder:
//   config.toml        the resolved configuration
//   trajectory.csv     particles every scene.trajectory_interval (docs/model.md)
//   timeseries.csv     every step: time, contacts, solver iterations and residual,
//                      kinetic energy, largest overlap
//   contacts.csv       contacts carrying load at the end
//   summary.json       run totals, solver convergence, version
//   checkpoint.bin     at every trajectory frame, on a stop and at the end
//                      (drivers/scene_checkpoint.hpp)
// A stopped run (Ctrl-C) writes its checkpoint and leaves its series as
// .part files; resumed, it continues them from the checkpoint with the bits
// of an uninterrupted run. A finished run resumed with a larger run.time
// runs on to it.
#include <atomic>

#include "drivers/run_options.hpp"
#include "io/config.hpp"

namespace dilatant {

struct SceneRunOptions {
  RunOptions run;
  // Continue the run in run.out_dir from its checkpoint (none there: start
  // anew; the CLI refuses that case first). Only under the configuration it
  // ran with, but for a larger run.time.
  bool resume = false;
  // Once set (Ctrl-C, Python), the run finishes its step, checkpoints and
  // returns interrupted.
  const std::atomic<bool>* stop_requested = nullptr;
  // If set, gets the fraction of run.time done after every step.
  std::atomic<double>* progress = nullptr;
};

struct SceneOutcome {
  long steps = 0;
  long unconverged_steps = 0;
  bool interrupted = false;
};

SceneOutcome run_scene(const Config& config, const SceneRunOptions& options);

}  // namespace dilatant
