#pragma once
// `dilatant predict --mu0 X --phi Y [--s-c S] [--json] [--table FILE]
// [--bulk-table FILE|none]`: the regime of spheres of boundary friction mu0 at
// volume fraction phi, from the first source that decides it: the flow states
// measured in bulk (Lees–Edwards ramps, analysis/bulk_flow_table.hpp), then
// the paper's model with the sediment's phi_max_BL(mu0)
// (analysis/jamming_table.hpp); the answer names its source. And the onset
// scale of thickening from our flow curves (analysis/onset_table.hpp).
// `dilatant predict --grid [--out DIR]`: the same over a grid of (mu0, phi),
// written to DIR/phase_diagram.csv and drawn (python/dilatant/plots/phase_diagram.py).
// `dilatant predict --model wyart_cates.json --phi Y [--stress S] [--sample NAME]`:
// the regime from a Wyart–Cates fit of measured or simulated flow curves
// (analysis/wyart_cates_prediction.hpp): a user's fit comes before both tables.
#include <CLI/CLI.hpp>
#include <string>

#include "app/python_script.hpp"

namespace dilatant {

struct PredictCommandArgs {
  // Required unless --grid.
  double mu0 = 0.0;
  double phi = 0.0;
  bool mu0_given = false;
  bool phi_given = false;
  double s_c = 0.0;  // set from friction_defaults::kSc by add_predict_command
  bool json = false;
  std::string table;       // empty: the built-in table
  std::string bulk_table;  // empty: the built-in one; "none": no bulk source
  bool grid = false;
  std::string out;  // --grid's folder (default out/predict)
  bool no_plots = false;
  std::string python = default_python();
  std::string model;   // a wyart_cates.json: answer from the fit
  std::string sample;  // which of its samples (empty: its only one)
  double stress = 0.0;
  bool stress_given = false;
};

CLI::App* add_predict_command(CLI::App& app, PredictCommandArgs& args);
int execute_predict_command(const PredictCommandArgs& args);

}  // namespace dilatant
