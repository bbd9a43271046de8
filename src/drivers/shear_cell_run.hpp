#pragma once
// Runs the shear cell (drivers/shear_cell.hpp; stress control, or rate control
// in the Lees-Edwards box) to run.strain (or until it jams) and writes its
// results folder (docs/shear-cell.md):
//   config.toml, summary.json, timeseries.csv, velocity_profile.csv,
//   sommerfeld_hist.csv, contacts.csv, checkpoint.bin, snapshots/*.vtp + cell.pvd
//
// Units: code units R = rho_p = tau = 1 inside; summary.json reports rates,
// stresses and viscosities in the paper's units (eta_f/(rho R^2), eta_f^2/(rho R^2),
// eta_f) — see docs/model.md.
#include <atomic>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <utility>

#include "drivers/run_options.hpp"
#include "drivers/step_dumps.hpp"
#include "io/config.hpp"

namespace dilatant {

struct CellRunOptions {
  CellRunOptions() = default;
  CellRunOptions(RunOptions run_options, bool resume_run = false,
                 const std::atomic<bool>* stop = nullptr)
      : run(std::move(run_options)), resume(resume_run), stop_requested(stop) {}

  RunOptions run;
  bool resume = false;
  // Set asynchronously (SIGINT/SIGTERM): write a checkpoint and stop.
  const std::atomic<bool>* stop_requested = nullptr;
  // Set asynchronously during the set-up: abandon it (SetupInterrupted,
  // drivers/setup_monitor.hpp). The CLI and Python pass their stop flag here
  // too; a sweep does not (a halted sweep lets its points reach a checkpoint).
  const std::atomic<bool>* stop_setup = nullptr;
  // Continuation along a flow curve (a rheometer ramp): instead of a new
  // packing, start from the final state in this checkpoint of another run of
  // the same cell (the neighbouring point of the curve). Particles, walls,
  // velocities and contact impulses are kept; strain, time and every
  // measurement start at zero, and the friction law and drive are this
  // config's. Ignored when resuming from out_dir's own checkpoint.
  std::filesystem::path start_from;
  // Step problems to write to disk (drivers/step_dumps.hpp); none by default.
  StepDumpSettings dumps;
  // When set, receives the fraction of run.strain done as the run goes (read
  // by another thread: the progress of a sweep).
  std::atomic<double>* progress = nullptr;
};

struct CellOutcome {
  long steps = 0;
  long unconverged_steps = 0;
  // The run's largest overlap, where it was, and the tolerance it is held to
  // (ShearCell::kOverlapTolerance): step -1 when there was none.
  double max_overlap = 0.0, overlap_tolerance = 0.0;
  long max_overlap_step = -1;
  long long max_overlap_body_i = -1, max_overlap_body_j = -1;
  // The run's largest contact residual (solver/contact_residual.hpp) and where.
  double contact_residual_max = 0.0;
  long contact_residual_step = -1;
  long long contact_residual_body_i = -1, contact_residual_body_j = -1;
  bool interrupted = false;
  bool jammed = false;
  // The summary.json the run wrote, as written; null when it wrote none
  // (interrupted, or resumed with nothing left to run: the file on disk is
  // the finished run's).
  nlohmann::json summary;
};

CellOutcome run_shear_cell(const Config& config, const CellRunOptions& options);

}  // namespace dilatant
