#pragma once
// summary.json of a shear-cell run: steady-state averages in the paper's units.
#include <nlohmann/json.hpp>

#include "drivers/shear_cell_state.hpp"
#include "io/config.hpp"
#include "measure/cell_units.hpp"
#include "measure/run_cost.hpp"

namespace dilatant {

// The volume fraction of the drive's bulk region in the state as it is
// (Drive::bulk_region): phi_bulk of a time-series row, or of a run without one.
double bulk_fraction(const ShearCellState& state);

nlohmann::json cell_summary(const Config& config, const CellUnits& units,
                            const ShearCellState& state, const RunCost& cost);

// Rows of sommerfeld_hist.csv: s_low,s_high,count,fraction (sticking contacts first, s = 0).
std::string sommerfeld_histogram_csv(const SommerfeldHistogram& h);

}  // namespace dilatant
