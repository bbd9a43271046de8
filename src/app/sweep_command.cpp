#include "app/sweep_command.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <iostream>
#include <optional>
#include <thread>

#include "app/plot_command.hpp"
#include "app/stop_request.hpp"
#include "dilatant/version.hpp"
#include "drivers/model_setup.hpp"
#include "io/input_error.hpp"
#include "sweep/mpi_session.hpp"
#include "sweep/point_folder.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runner.hpp"
#if DILATANT_WITH_MPI
#include "sweep/mpi_scheduler.hpp"
#endif

namespace dilatant {

CLI::App* add_sweep_command(CLI::App& app, SweepCommandArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run many shear cells from one sweep file: a run configuration in which any key may hold "
      "a list of values (friction.mu0 = [0.1, 0.3], fluid.lambda = [1.0, 10.0, 100.0]; for "
      "cell.size a list of arrays); the points are the full grid of the lists, or the "
      "[[points]] tables of the file. Optional [sweep] table: jobs, continuation (each lambda "
      "of a flow curve starts from the previous one's final state), continuation_strain, "
      "continuation_transient_strain, stop_at_jam, confirm_jams, cold_start_phi, refines (extra "
      "stresses of another sweep's ramps, from their states), extend_unsteady_to (a point "
      "that is not steady runs on, one averaging window at a time, up to this strain). Points run "
      "side by side, each in "
      "DIR/points/NNN-label/; DIR/flowcurves.csv gets one row per point (swept keys, status, "
      "error, summary fields) after every finished point; DIR/sweep.toml is the resolved sweep. "
      "Running the same command again skips finished points and resumes the others; Ctrl-C "
      "checkpoints the running points. At the end, the flow-curve analysis (DIR/analysis/: "
      "regime per curve) and the plots (DIR/plots/). Under mpirun (or srun) the points are "
      "shared among the ranks, one unit (point or chain) at a time to whichever rank is free; "
      "DIR must be on a filesystem all ranks see. See docs/sweeps.md and docs/cluster.md.");
  cmd->add_option("config", args.config, "Sweep file (TOML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--out", args.out, "Output folder (default: out/<config name>)");
  cmd->add_option("-j,--jobs", args.jobs,
                  "Points run side by side (default: [sweep] jobs, else one per core; 0 = one "
                  "per core). Under mpirun: per rank (default: [sweep] jobs, else 1; 0 = the "
                  "node's cores shared among its ranks); see docs/cluster.md")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("-s,--set", args.overrides,
                  "Override a key of the sweep file: dotted.key=TOML value; a list sweeps it, "
                  "e.g. 'fluid.lambda=[1.0, 10.0]'; sweep.jobs=2 sets [sweep] (repeatable)")
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", args.quiet, "No progress, notes or final message");
  cmd->add_flag("--progress", args.progress,
                "Draw the progress line even when stderr is not a terminal (under mpirun, "
                "whose ranks write to a pipe)");
  cmd->add_flag("--no-plots", args.no_plots, "Write the tables only, no plots");
  cmd->add_option("--python", args.python, "Python with matplotlib that draws the plots")
      ->capture_default_str();
  cmd->add_option("--plot-script", args.plot_script,
                  "The plotting script (default: dilatant/plots/sweep.py of the installed package, "
                  "else of this source tree)");
  return cmd;
}

namespace {

int resolve_jobs(int from_command_line, int from_file) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (from_command_line > 0) return from_command_line;
  if (from_command_line == 0) return cores;
  return from_file > 0 ? from_file : cores;
}

// Under MPI the ranks of a node share its cores, and a rank is usually given
// one core (or the cores of its solver.threads): one point at a time unless
// told otherwise.
int resolve_jobs_per_rank(int from_command_line, int from_file, int ranks_on_node) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (from_command_line > 0) return from_command_line;
  if (from_command_line == 0) return std::max(1, cores / std::max(1, ranks_on_node));
  return from_file > 0 ? from_file : 1;
}

// The sweep file, read by every rank. Under MPI the ranks agree first that
// all of them read it (else none runs anything); rank 0 reports the error of
// the input, another rank only one that rank 0 did not have. Returns the exit
// code of a rank that must end, or nothing.
std::optional<int> load_plan(const SweepCommandArgs& args, const sweep::MpiSession& mpi,
                             std::optional<sweep::SweepPlan>& plan) {
  if (mpi.size() == 1) {
    plan.emplace(sweep::load_sweep(args.config, args.overrides));
    return std::nullopt;
  }
  std::exception_ptr error;
  bool input_error = false;
  try {
    plan.emplace(sweep::load_sweep(args.config, args.overrides));
  } catch (const InputError&) {
    error = std::current_exception();
    input_error = true;
  } catch (const std::exception&) {
    error = std::current_exception();
  }
  if (mpi.all_ranks(error == nullptr)) return std::nullopt;
  const bool rank0_read_it = mpi.on_rank0(error == nullptr);
  if (mpi.rank() == 0) {
    if (error != nullptr) std::rethrow_exception(error);
    throw std::runtime_error(
        "another rank of the MPI job could not read the sweep (its message is above)");
  }
  if (error == nullptr) return 0;
  if (rank0_read_it) {
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      std::cerr << fmt::format("dilatant: error on rank {}: {}\n", mpi.rank(), e.what());
    }
  }
  return input_error ? 2 : 1;
}

}  // namespace

int execute_sweep_command(const SweepCommandArgs& args) {
  // MPI only when an MPI launcher started this process (sweep/mpi_session.hpp).
  sweep::MpiSession mpi;
  const bool on_ranks = mpi.size() > 1;
  const bool lead = mpi.rank() == 0;  // prints, analyses and plots
  std::optional<sweep::SweepPlan> loaded;
  if (const auto code = load_plan(args, mpi, loaded)) return *code;
  const sweep::SweepPlan& plan = *loaded;
  const std::filesystem::path out =
      args.out.empty() ? std::filesystem::path("out") / std::filesystem::path(args.config).stem()
                       : std::filesystem::path(args.out);
  sweep::SweepRunOptions options;
  options.out = out;
  options.jobs =
      on_ranks ? resolve_jobs_per_rank(args.jobs, plan.settings.jobs, mpi.ranks_on_this_node())
               : resolve_jobs(args.jobs, plan.settings.jobs);
  if (!on_ranks && !args.quiet) {
    // The points' solver threads (after the cap), the most any point asks.
    int threads = 1;
    for (const sweep::SweepPoint& p : plan.points)
      threads = std::max(threads, make_solver_settings(p.config.solver).threads);
    if (const std::string w = oversubscription_warning(options.jobs, threads); !w.empty())
      std::cerr << w << "\n";
  }
  // A study resumed by another binary would mix versions in one table (said
  // once: by the only process, or by rank 0 of an MPI job).
  if (lead && !args.quiet) {
    for (const auto& [version, count] : sweep::other_versions_of_done_points(plan, out))
      std::cerr << fmt::format(
          "dilatant: note: {} finished point(s) in {} were run by version {}, this is {}: the "
          "table will mix versions (to finish a study with the binary it started with: "
          "scripts/pinned-binary.sh, docs/sweeps.md)\n",
          count, out.string(), version, kVersion);
  }
  options.show_progress = lead && !args.quiet && (args.progress || isatty(STDERR_FILENO));
  options.report_failures = lead && !args.quiet;
  // SIGINT/SIGTERM: the running points write a checkpoint and stop.
  options.stop = stop_on_interrupt();
#if DILATANT_WITH_MPI
  const sweep::SweepOutcome outcome =
      on_ranks ? sweep::run_sweep_on_ranks(plan, options, mpi) : sweep::run_sweep(plan, options);
#else
  const sweep::SweepOutcome outcome = sweep::run_sweep(plan, options);
#endif
  // The other ranks' part is over: they exit now, while rank 0 analyses.
  mpi.finalize();
  if (!lead) return 0;

  if (outcome.interrupted) {
    std::cerr << fmt::format(
        "dilatant: interrupted: {} of {} points done, {} not finished (checkpoints written); run "
        "the same command again to resume\n",
        outcome.done, outcome.points, outcome.pending);
    return 1;
  }
  if (outcome.done > 0)
    analyse_and_plot_sweep(out, !args.no_plots, args.python, args.plot_script, args.quiet);
  if (!args.quiet) {
    std::cout << fmt::format(
        "dilatant: sweep of {} points: {} done{}, {} failed{}; results in {}\n", outcome.points,
        outcome.done,
        outcome.skipped > 0 ? fmt::format(" ({} of them before this run)", outcome.skipped) : "",
        outcome.failed,
        outcome.above_jam > 0
            ? fmt::format(", {} not run above the jam of their ramp", outcome.above_jam)
            : "",
        (out / "flowcurves.csv").string());
  }
  // As `dilatant run` warns about its own: a sweep whose points' solver
  // stopped at its cap says so, once, with the worst point.
  if (!args.quiet && outcome.unconverged_points > 0)
    std::cerr << fmt::format(
        "dilatant: warning: {} of {} points have steps that did not converge within "
        "solver.max_iterations, up to {:.2g}% of a point's ({}; frac_steps_unconverged in "
        "flowcurves.csv)\n",
        outcome.unconverged_points, outcome.points, 100.0 * outcome.most_unconverged,
        outcome.most_unconverged_point);
  if (outcome.failed > 0) {
    std::cerr << fmt::format(
        "dilatant: {} of {} points failed (see the error column of flowcurves.csv); run the "
        "same command again to retry them\n",
        outcome.failed, outcome.points);
    return 1;
  }
  return 0;
}

}  // namespace dilatant
