#pragma once
// Runs a scene to run.time and writes its results folder:
//   config.toml        the resolved configuration
//   trajectory.csv     particles every scene.trajectory_interval (docs/model.md)
//   timeseries.csv     every step: time, contacts, solver iterations and residual,
//                      kinetic energy, largest overlap
//   contacts.csv       contacts carrying load at the end
//   summary.json       run totals, solver convergence, version
#include "drivers/run_options.hpp"
#include "io/config.hpp"

namespace dilatant {

struct SceneOutcome {
  long steps = 0;
  long unconverged_steps = 0;
};

SceneOutcome run_scene(const Config& config, const RunOptions& options);

}  // namespace dilatant
