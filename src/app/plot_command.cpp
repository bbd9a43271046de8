#include "app/plot_command.hpp"

#include <fmt/format.h>

#include <iostream>

#include "app/python_script.hpp"
#include "io/input_error.hpp"
#include "sweep/sweep_analysis.hpp"

namespace dilatant {

CLI::App* add_plot_command(CLI::App& app, PlotCommandArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Figures of a sweep folder (written by `dilatant sweep`), as PNG and SVG in DIR/plots/: "
      "eta vs gamma_dot per mu0 and phi (paper Fig. 2), eta vs gamma_dot with the stresses "
      "labelled (Fig. 1b), P(s) at several stresses with the friction law (Fig. 1c), P_BL and "
      "P_HD vs gamma_dot (Fig. 1d). Points outside the model's validity are drawn hollow grey, "
      "jammed points marked. Redoes the flow-curve analysis (DIR/analysis/) first. Needs "
      "Python with matplotlib; without it the plots are skipped with one line on stderr. See "
      "docs/sweeps.md.");
  cmd->add_option("dir", args.dir, "The sweep's folder (holding flowcurves.csv)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--python", args.python, "Python with matplotlib that draws the plots")
      ->capture_default_str();
  cmd->add_option("--plot-script", args.plot_script,
                  "The plotting script (default: dilatant/plots/sweep.py of the installed package, "
                  "else of this source tree)");
  cmd->add_flag("-q,--quiet", args.quiet, "No message on stdout");
  return cmd;
}

bool analyse_and_plot_sweep(const std::filesystem::path& dir, bool plots, const std::string& python,
                            const std::string& plot_script, bool quiet) {
  const std::string note = sweep::analyse_sweep(dir);
  if (!note.empty() && !quiet)
    std::cerr << fmt::format("dilatant: note: no flow-curve analysis ({})\n", note);
  if (!plots) return false;
  const std::string script = plot_script.empty() ? dilatant::plot_script("sweep.py") : plot_script;
  const std::string failure = run_plot_script(python, script, dir);
  if (failure.empty()) return true;
  std::cerr << fmt::format("dilatant: plots skipped ({}); the tables are complete\n", failure);
  return false;
}

int execute_plot_command(const PlotCommandArgs& args) {
  const std::filesystem::path dir(args.dir);
  if (!std::filesystem::is_regular_file(dir / "flowcurves.csv"))
    throw InputError(
        fmt::format("{}: no flowcurves.csv here: not the folder of a sweep", dir.string()));
  const bool drawn = analyse_and_plot_sweep(dir, true, args.python, args.plot_script, args.quiet);
  if (drawn && !args.quiet)
    std::cout << fmt::format("dilatant: figures in {}\n", (dir / "plots").string());
  return 0;
}

}  // namespace dilatant
