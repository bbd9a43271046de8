#pragma once
// `dilatant sweep CONFIG.toml [--out DIR] [--jobs N] [--set key=value ...]`:
// many shear-cell runs from one sweep file (sweep/sweep_plan.hpp), side by
// side, resumable; then the flow-curve analysis and the plots (docs/sweeps.md).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/python_script.hpp"

namespace dilatant {

struct SweepCommandArgs {
  std::string config;
  std::string out;  // empty: out/<config stem>
  int jobs = -1;    // -1: [sweep] jobs, else one per core; 0: one per core
  std::vector<std::string> overrides;
  bool quiet = false;
  bool progress = false;  // the progress line even when stderr is no terminal (mpirun)
  bool no_plots = false;
  std::string python = default_python();
  std::string plot_script;  // empty: plot_script() (app/python_script.hpp)
};

CLI::App* add_sweep_command(CLI::App& app, SweepCommandArgs& args);
// Returns the process exit code (1 when a point failed or the sweep was
// interrupted); throws InputError on bad input.
int execute_sweep_command(const SweepCommandArgs& args);

}  // namespace dilatant
