#pragma once
// `dilatant plot DIR`: the figures of a sweep (paper Figs. 1b-d and 2) from
// its folder, redrawn: the flow-curve analysis again (DIR/analysis/), then
// python/dilatant/plots/sweep.py into DIR/plots/ (PNG and SVG; docs/sweeps.md "Plots").
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "app/python_script.hpp"

namespace dilatant {

struct PlotCommandArgs {
  std::string dir;
  std::string python = default_python();
  std::string plot_script;  // empty: plot_script() (app/python_script.hpp)
  bool quiet = false;
};

CLI::App* add_plot_command(CLI::App& app, PlotCommandArgs& args);
int execute_plot_command(const PlotCommandArgs& args);

// The analysis and plots of a sweep folder, as `dilatant sweep` ends and
// `dilatant plot` does; problems are reported on stderr in one line each
// (never an error: the tables stand without them). True when plots were drawn.
bool analyse_and_plot_sweep(const std::filesystem::path& dir, bool plots, const std::string& python,
                            const std::string& plot_script, bool quiet);

}  // namespace dilatant
