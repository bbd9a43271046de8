#pragma once
// Runs the stress-controlled shear cell to run.strain (or until it jams) and
// writes its results folder (SPEC §2):
//   config.toml, summary.json, timeseries.csv, velocity_profile.csv,
//   sommerfeld_hist.csv, contacts.csv, checkpoint.bin, snapshots/*.vtp + cell.pvd
//
// Units: code units R = rho_p = tau = 1 inside; summary.json reports rates,
// stresses and viscosities in the paper's units (eta_f/(rho R^2), eta_f^2/(rho R^2),
// eta_f) — see docs/model.md.
#include <atomic>

#include "drivers/scene_run.hpp"
#include "io/config.hpp"

namespace dilatant {

struct CellRunOptions {
  RunOptions run;
  bool resume = false;
  // Set asynchronously (SIGINT/SIGTERM): write a checkpoint and stop.
  const std::atomic<bool>* stop_requested = nullptr;
};

struct CellOutcome {
  long steps = 0;
  long unconverged_steps = 0;
  bool interrupted = false;
  bool jammed = false;
};

CellOutcome run_shear_cell(const Config& config, const CellRunOptions& options);

}  // namespace dilatant
