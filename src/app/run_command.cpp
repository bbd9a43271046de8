#include "app/run_command.hpp"

#include <fmt/format.h>

#include <iostream>
#include <stdexcept>

#include "app/stop_request.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/scene_run.hpp"
#include "drivers/setup_monitor.hpp"
#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"
#include "io/config_keys.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace dilatant {

namespace {

// A count or strain of the --dump-* options: a number >= 0, said in one line.
const CLI::Validator kAtLeastZero(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && value >= 0.0) return "";
      } catch (const std::exception&) {
      }
      return "'" + text + "' is not a number >= 0";
    },
    ">= 0", "at least zero");

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunCommandArgs& args) {
  CLI::App* run = app.add_subcommand(
      "run",
      "Run one simulation. CONFIG is a TOML file with a [scene] table (particles from CSV, "
      "planes, gravity) or a [cell] table (the paper's shear cell). Without CONFIG, runs the "
      "built-in default cell (phi 0.58, mu0 0.1). Results go to --out: config.toml (resolved), "
      "summary.json, timeseries.csv, contacts.csv, and trajectory.csv for scenes.");
  run->add_option("config", args.config, "TOML configuration file")->check(CLI::ExistingFile);
  run->add_option("-o,--out", args.out, "Output folder (default: out/<config name>)");
  run->add_option("-s,--set", args.overrides,
                  "Override a config key: dotted.key=TOML value, e.g. friction.mu0=0.3, "
                  "'cell.size=[10.0, 6.0, 12.0]', friction.law=coulomb (repeatable)")
      ->allow_extra_args(false);
  run->add_flag("-q,--quiet", args.quiet, "No progress or final messages");
  // Every configuration key, its default, range and unit, from the one table of keys.
  run->footer(config_keys_help());
  run->add_flag("--resume", args.resume,
                "Continue from OUT/checkpoint.bin (same config; a larger run.strain, or a scene's "
                "run.time, extends a finished run) instead of starting anew; the result is "
                "identical to an uninterrupted run");
  run->add_option("--start-from", args.start_from,
                  "Shear cell: start from the state in this checkpoint.bin (a run of the same "
                  "cell size), under this config, strain counted from 0 (a sweep's continuation)")
      ->check(CLI::ExistingFile)
      ->excludes("--resume");
  // Step problems on disk, for measuring solver methods (drivers/step_dumps.hpp,
  // bench/tools/solve_step.cpp). Not config keys: they change no result.
  auto* dumps = run->add_option("--dump-steps", args.dumps.dir,
                                "Shear cell: write the states chosen steps start from into this "
                                "folder (checkpoints, with config.toml and index.csv), each "
                                "loadable to solve that step's contact problem again");
  run->add_option("--dump-every", args.dumps.every,
                  "With --dump-steps: every N-th step from --dump-from-strain on (0: none)")
      ->check(kAtLeastZero)
      ->needs(dumps);
  run->add_option("--dump-from-strain", args.dumps.from_strain,
                  "With --dump-steps: the strain regular dumps start at (default 0)")
      ->check(kAtLeastZero)
      ->needs(dumps);
  run->add_option("--dump-max", args.dumps.max_regular,
                  "With --dump-steps: at most this many regular dumps (default 10)")
      ->check(kAtLeastZero)
      ->needs(dumps);
  run->add_option("--dump-unconverged", args.dumps.max_unconverged,
                  "With --dump-steps: also the first K steps that end unconverged (default 0)")
      ->check(kAtLeastZero)
      ->needs(dumps);
  return run;
}

namespace {

// A run whose solver did not converge says so, never silently.
void warn_if_unconverged(const Config& config, long steps, long unconverged) {
  if (unconverged == 0) return;
  std::cerr << fmt::format(
      "dilatant: warning: {} of {} steps did not converge within solver.max_iterations = {} "
      "(see timeseries.csv, summary.json)\n",
      unconverged, steps, config.solver.max_iterations);
}

int run_cell(const Config& config, const RunOptions& options, bool resume,
             const std::string& start_from, const StepDumpSettings& dumps) {
  // SIGINT/SIGTERM: finish the step, write a checkpoint, exit cleanly.
  CellRunOptions cell_options{options, resume, stop_on_interrupt()};
  cell_options.stop_setup = cell_options.stop_requested;  // Ctrl-C during a long set-up
  cell_options.start_from = start_from;
  cell_options.dumps = dumps;
  CellOutcome outcome;
  try {
    outcome = run_shear_cell(config, cell_options);
  } catch (const SetupInterrupted& e) {
    std::cerr << fmt::format("dilatant: {}\n", e.what());
    return 1;
  }
  if (outcome.interrupted) {
    std::cerr << fmt::format(
        "dilatant: interrupted; checkpoint written to {}; continue with "
        "--resume\n",
        (options.out_dir / "checkpoint.bin").string());
    return 1;
  }
  warn_if_unconverged(config, outcome.steps, outcome.unconverged_steps);
  if (outcome.unconverged_steps > 0 && outcome.contact_residual_step >= 0) {
    const bool plane = outcome.contact_residual_body_j < 0;
    std::cerr << fmt::format(
        "dilatant: warning: the largest contact residual, {:.3g} of the load's impulse "
        "tau (2R)^2 dt, was at "
        "step {} between body {} and {} {} (summary.json: contact_residual_max_step, "
        "contact_residual_max_bodies)\n",
        outcome.contact_residual_max, outcome.contact_residual_step,
        outcome.contact_residual_body_i, plane ? "plane" : "body",
        plane ? -outcome.contact_residual_body_j - 1 : outcome.contact_residual_body_j);
  }
  if (outcome.max_overlap > outcome.overlap_tolerance) {
    const bool plane = outcome.max_overlap_body_j < 0;
    std::cerr << fmt::format(
        "dilatant: warning: overlap {:.3g} R at step {} between body {} and {} {}, above the "
        "tolerance {:.3g} R (summary.json: overlap_exceeded)\n",
        outcome.max_overlap, outcome.max_overlap_step, outcome.max_overlap_body_i,
        plane ? "plane" : "body",
        plane ? -outcome.max_overlap_body_j - 1 : outcome.max_overlap_body_j,
        outcome.overlap_tolerance);
  }
  // A result that is not valid says why (exit 0 all the same: the run did
  // what it was asked; validity is the result's, docs/shear-cell.md).
  const nlohmann::json& summary = outcome.summary;
  const bool invalid = summary.is_object() && summary.contains("invalid_reasons") &&
                       !summary["invalid_reasons"].empty();
  if (invalid) {
    std::string reasons;
    for (const auto& reason : summary["invalid_reasons"])
      reasons += (reasons.empty() ? "" : "; ") + reason.get<std::string>();
    std::cerr << fmt::format(
        "dilatant: warning: the result is not valid: {} (summary.json: invalid_reasons)\n",
        reasons);
  }
  if (!options.quiet) {
    std::cout << fmt::format("dilatant: {} steps{}; results in {}{}\n", outcome.steps,
                             outcome.jammed ? " (the cell jammed)" : "", options.out_dir.string(),
                             invalid ? " (not valid: see the warning)" : "");
  }
  return 0;
}

}  // namespace

int execute_run_command(const RunCommandArgs& args) {
  const Config config = args.config.empty() ? default_cell_config(args.overrides)
                                            : load_config(args.config, args.overrides);
  if (config.sediment() != nullptr)
    throw InputError(config.source + ": a [sediment] config is run by dilatant jam");
  if (!args.quiet)
    for (const std::string& note : config.notes) std::cerr << note << "\n";
  if (const std::string cap = thread_cap_warning(config.solver); !cap.empty())
    std::cerr << cap << "\n";
  RunOptions options;
  options.quiet = args.quiet;
  if (!args.start_from.empty() && !config.cell())
    throw InputError(args.start_from + ": --start-from needs a shear-cell run ([cell])");
  options.out_dir =
      args.out.empty()
          ? std::filesystem::path("out") /
                (args.config.empty() ? std::string("default")
                                     : std::filesystem::path(args.config).stem().string())
          : std::filesystem::path(args.out);
  if (args.resume) require_checkpoint_to_resume(options.out_dir);
  if (!args.dumps.dir.empty() && !config.cell())
    throw InputError(args.dumps.dir.string() + ": --dump-steps needs a shear-cell run ([cell])");
  if (!args.dumps.dir.empty() && !args.dumps.any())
    throw InputError(args.dumps.dir.string() +
                     ": --dump-steps chooses no step: give --dump-every N (N > 0) or "
                     "--dump-unconverged K (K > 0)");
  if (config.cell()) return run_cell(config, options, args.resume, args.start_from, args.dumps);
  // SIGINT/SIGTERM: finish the step, write a checkpoint, exit cleanly.
  const SceneOutcome outcome = run_scene(config, {options, args.resume, stop_on_interrupt()});
  if (outcome.interrupted) {
    std::cerr << fmt::format(
        "dilatant: interrupted; checkpoint written to {}; continue with --resume\n",
        (options.out_dir / "checkpoint.bin").string());
    return 1;
  }
  warn_if_unconverged(config, outcome.steps, outcome.unconverged_steps);
  if (!args.quiet) {
    std::cout << fmt::format("dilatant: {} steps done; results in {}\n", outcome.steps,
                             options.out_dir.string());
  }
  return 0;
}

}  // namespace dilatant
