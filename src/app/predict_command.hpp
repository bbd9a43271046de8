#pragma once
// `dilatant predict --mu0 X --phi Y [--json] [--table FILE]`: the regime the
// paper's model assigns to spheres of boundary friction mu0 at volume fraction
// phi (analysis/jamming_table.hpp), from the measured phi_max_BL(mu0).
#include <CLI/CLI.hpp>
#include <string>

namespace dilatant {

struct PredictCommandArgs {
  double mu0 = 0.0;
  double phi = 0.0;
  bool json = false;
  std::string table;  // empty: the built-in table
};

CLI::App* add_predict_command(CLI::App& app, PredictCommandArgs& args);
int execute_predict_command(const PredictCommandArgs& args);

}  // namespace dilatant
