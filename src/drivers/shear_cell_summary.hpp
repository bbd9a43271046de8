#pragma once
// summary.json of a shear-cell run: steady-state averages in the paper's units.
#include <nlohmann/json.hpp>

#include "drivers/shear_cell_state.hpp"
#include "io/config.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

// Physical parameters in code units (R = rho_p = tau = 1 by convention, but
// the formulas keep the symbols so a config with other values stays right).
struct CellUnits {
  double lambda = 0.0;
  double eta_f = 0.0;        // sqrt(tau rho_p) R / lambda
  double rate_unit = 0.0;    // eta_f / (rho_p R^2): paper's unit of shear rate
  double stress_unit = 0.0;  // eta_f^2 / (rho_p R^2): paper's unit of stress
};
CellUnits cell_units(const Config& config);

nlohmann::json cell_summary(const Config& config, const ShearCellState& state, const RunCost& cost);

// Rows of sommerfeld_hist.csv: s_low,s_high,count,fraction (sticking contacts first, s = 0).
std::string sommerfeld_histogram_csv(const SommerfeldHistogram& h);

}  // namespace dilatant
