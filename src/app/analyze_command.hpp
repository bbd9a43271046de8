#pragma once
// `dilatant analyze INPUT [--out DIR] [--no-plots] [options]`, or
// `dilatant analyze --list FILE` (the steps of a rheometer export): the rheometer
// analysis (docs/analysis.md) of a manifest of rheometer files or of a sweep's
// flowcurves.csv. The numbers come from the library (src/analysis); the plots
// are drawn from the written files by python/dilatant/plots/analysis.py.
// `--model wyart-cates` adds the Wyart–Cates fit of each sample
// (analysis/wyart_cates_report.hpp) and its overlay and flow-state map.
#include <CLI/CLI.hpp>
#include <string>

#include "analysis/analysis_settings.hpp"
#include "analysis/wyart_cates_fit.hpp"
#include "app/python_script.hpp"

namespace dilatant {

struct AnalyzeCommandArgs {
  std::string input;
  std::string list;  // --list FILE: show the file's steps and exit
  std::string out;   // empty: out/analysis/<input stem>
  bool no_plots = false;
  bool quiet = false;
  std::string python = default_python();
  std::string plot_script;  // empty: plot_script() (app/python_script.hpp)
  analysis::AnalysisSettings settings;
  std::string model;  // empty, or "wyart-cates"
  analysis::WyartCatesSettings wyart_cates;
};

CLI::App* add_analyze_command(CLI::App& app, AnalyzeCommandArgs& args);
// Returns the process exit code; throws InputError on bad input.
int execute_analyze_command(const AnalyzeCommandArgs& args);

}  // namespace dilatant
