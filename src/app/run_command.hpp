#pragma once
// `dilatant run [CONFIG.toml] [--out DIR] [--set key=value ...] [--quiet]`
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "drivers/step_dumps.hpp"

namespace dilatant {

struct RunCommandArgs {
  std::string config;  // empty: the built-in default shear cell
  std::string out;     // empty: out/<config stem>
  std::vector<std::string> overrides;
  bool quiet = false;
  bool resume = false;
  std::string start_from;  // shear cell: start from this checkpoint's state (--start-from)
  StepDumpSettings dumps;  // shear cell: step problems to write (--dump-*)
};

CLI::App* add_run_command(CLI::App& app, RunCommandArgs& args);
// Returns the process exit code; throws InputError on bad input.
int execute_run_command(const RunCommandArgs& args);

}  // namespace dilatant
