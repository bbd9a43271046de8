#pragma once
// `dilatant jam [CONFIG.toml] [--out DIR] [--set key=value ...] [--resume]`: simulated
// centrifugation (drivers/sediment_run.hpp), the jamming fraction phi_max of a
// friction mu0 (the paper's phi_max_BL, its Fig. 3a and 4).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace dilatant {

struct JamCommandArgs {
  std::string config;  // empty: the built-in [sediment]
  std::string out;
  std::vector<std::string> overrides;
  bool quiet = false;
  bool resume = false;
};

CLI::App* add_jam_command(CLI::App& app, JamCommandArgs& args);
int execute_jam_command(const JamCommandArgs& args);

}  // namespace dilatant
