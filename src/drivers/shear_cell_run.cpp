#include "drivers/shear_cell_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <optional>

#include "drivers/setup_monitor.hpp"
#include "drivers/shear_cell.hpp"
#include "io/atomic_file.hpp"
#include "io/config_compare.hpp"
#include "io/folder_lock.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

namespace {

CellOutcome outcome_of(const ShearCell& cell, bool interrupted) {
  const ShearCellState& state = cell.state();
  const SolverRecord solver = SolverRecord::of(state.measurements.rows);
  CellOutcome outcome;
  outcome.steps = state.steps;
  outcome.unconverged_steps = static_cast<long>(solver.unconverged);
  if (const FlowRow* r = solver.deepest; r != nullptr && r->max_overlap_step >= 0.0) {
    outcome.max_overlap = r->max_overlap;
    outcome.max_overlap_step = static_cast<long>(r->max_overlap_step);
    outcome.max_overlap_body_i = static_cast<long long>(r->max_overlap_body_i);
    outcome.max_overlap_body_j = static_cast<long long>(r->max_overlap_body_j);
  }
  if (const FlowRow* r = solver.worst_residual; r != nullptr) {
    outcome.contact_residual_max = r->contact_residual_max;
    outcome.contact_residual_step = static_cast<long>(r->contact_residual_step);
    outcome.contact_residual_body_i = static_cast<long long>(r->contact_residual_body_i);
    outcome.contact_residual_body_j = static_cast<long long>(r->contact_residual_body_j);
  }
  outcome.overlap_tolerance = ShearCell::kOverlapTolerance * cell.config().cell()->radius_min;
  outcome.jammed = state.jam.jammed;
  outcome.interrupted = interrupted;
  return outcome;
}

}  // namespace

namespace {

// A state to start from that is not a checkpoint of this cell is bad input
// (exit 2), named with its file by the message.
ShearCell continued(const Config& config, const std::filesystem::path& start_from) {
  try {
    return ShearCell::continued(config, start_from);
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

// The run in `out` resumed from its checkpoint: only under the configuration
// it ran with (its config.toml), and a checkpoint that cannot be read is bad
// input naming its file (exit 2), like any other file given to dilatant.
// run.strain alone may differ: a larger one extends the run (a finished one
// too: its checkpoint holds the state before the last row was closed), with
// the bits of a run made that long from the start; a smaller one is refused.
// run.transient_strain may move too, but only to or beyond the run's
// run.strain there: the averages past the transient then start anew (a fresh
// window after everything the run had reached: how a sweep runs on a point
// that is not steady, sweep/unsteady_extension.hpp); a transient moved into
// the strain already run would leave the profile averaged over another window
// than the rows.
ShearCell resumed(const Config& config, const std::filesystem::path& out) {
  const auto written = out / "config.toml";
  static constexpr std::string_view kExtensible[] = {"run.strain", "run.transient_strain"};
  bool transient_moved = false;
  if (const auto there = resumable_run_config(
          out, config, kExtensible,
          "only run.strain may grow, and run.transient_strain move beyond it")) {
    const double before = (*there)["run"]["strain"].value_or(0.0);
    if (config.run.strain < before)
      throw InputError(fmt::format(
          "{}: run.strain = {} is below the run's there ({}): --resume extends a run, it cannot "
          "shorten one",
          written.string(), config.run.strain, before));
    const double transient_before = (*there)["run"]["transient_strain"].value_or(0.0);
    transient_moved = config.run.transient_strain != transient_before;
    if (transient_moved && config.run.transient_strain < before)
      throw InputError(fmt::format(
          "{}: run.transient_strain = {} differs from the run's there ({}) and lies within the "
          "strain it ran ({}): on --resume the transient may only move to {} or beyond, where "
          "the averages start anew",
          written.string(), config.run.transient_strain, transient_before, before, before));
  }
  try {
    return ShearCell::resumed(config, out / "checkpoint.bin", transient_moved);
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

}  // namespace

CellOutcome run_shear_cell(const Config& config, const CellRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto& out = options.run.out_dir;
  const auto checkpoint = out / "checkpoint.bin";
  prepare_output_folder(out);
  // Held to the end of the run: a second run on this folder would resume from
  // the same checkpoint and overwrite this one's (io/folder_lock.hpp).
  const FolderLock lock(out, "a shear-cell run");

  const bool resuming = options.resume && std::filesystem::exists(checkpoint);
  const bool progress = !options.run.quiet && isatty(STDERR_FILENO);
  ShearCell cell = [&] {
    // A large cell's set-up takes a while: shown on a terminal, and stopped by
    // the stop flag (SetupInterrupted; nothing written yet but config-free
    // folders).
    auto last_shown = std::chrono::steady_clock::now();
    bool shown = false;
    const ScopedSetupMonitor monitor(
        {.stop = options.stop_setup, .progress = [&](std::string_view stage, double f) {
           if (!progress ||
               std::chrono::steady_clock::now() - last_shown < std::chrono::milliseconds(500))
             return;
           std::cerr << fmt::format("\rsetting up: {}, {:.0f}%   ", stage, 100.0 * f) << std::flush;
           last_shown = std::chrono::steady_clock::now();
           shown = true;
         }});
    ShearCell built = resuming                      ? resumed(config, out)
                      : !options.start_from.empty() ? continued(config, options.start_from)
                                                    : ShearCell(config);
    if (shown) std::cerr << "\r\033[K" << std::flush;
    return built;
  }();
  // A fresh run owns the folder's run files: an earlier run's snapshots and
  // cell.pvd would otherwise stay beside the new results (issue 31). Only
  // after the cell is built: --start-from may read this very folder.
  if (!resuming)
    remove_earlier_results(out,
                           {"checkpoint.bin", "timeseries.csv", "velocity_profile.csv",
                            "sommerfeld_hist.csv", "contacts.csv", "summary.json", "cell.pvd"},
                           {{"snapshots", {"particles_", "contacts_"}}});
  const double build_s = seconds_since(start);
  const double strain_at_start = cell.state().strain;
  if (options.resume && cell.done()) {
    // Nothing left to run: keep the finished run's files as they are.
    CellOutcome outcome;
    outcome.steps = cell.state().steps;
    outcome.jammed = cell.state().jam.jammed;
    return outcome;
  }
  write_file_atomically(out / "config.toml", resolved_toml(config));

  const auto report_fraction = [&] {
    if (options.progress != nullptr) options.progress->store(cell.fraction_done());
  };
  report_fraction();
  auto last_progress = std::chrono::steady_clock::now();
  std::optional<StepDumper> dumper;
  if (options.dumps.any()) dumper.emplace(options.dumps, config);
  while (!cell.done()) {
    if (dumper) dumper->before_step(cell);
    const StepReport& report = cell.step();
    if (dumper) dumper->after_step(cell, report);
    if (cell.snapshot_due()) cell.write_snapshot(out);
    report_fraction();
    const bool stop = options.stop_requested != nullptr && options.stop_requested->load();
    if (cell.checkpoint_due() || stop) {
      cell.write_checkpoint(checkpoint);
      cell.write_series(out);
    }
    if (stop) {
      if (progress) std::cerr << "\n";
      return outcome_of(cell, /*interrupted=*/true);
    }
    if (progress &&
        std::chrono::steady_clock::now() - last_progress > std::chrono::milliseconds(500)) {
      std::cerr << "\r" << cell.progress_line(seconds_since(start)) << std::flush;
      last_progress = std::chrono::steady_clock::now();
    }
  }
  if (progress) std::cerr << "\n";
  // The checkpoint before the last, partial row is closed: a --resume with a
  // larger run.strain continues that row as an uninterrupted run would.
  cell.write_checkpoint(checkpoint);
  cell.finish();
  RunCost cost = cell.cost();
  cost.build_s = build_s;
  cost.strain = cell.state().strain - strain_at_start;
  cost.wall_s = seconds_since(start);
  CellOutcome outcome = outcome_of(cell, /*interrupted=*/false);
  outcome.summary = cell.write_results(out, cost);
  return outcome;
}

}  // namespace dilatant
