#pragma once
// The paper's phase diagram (Fernandez et al. 2013, Fig. 4) drawn from our
// tables: the regime `dilatant predict` gives at every node of a grid of
// (mu0, phi) — the bulk flow curves' where they decide (bulk_flow_table.hpp),
// else the sediment table's (predict_regime) — as the CSV that
// python/dilatant/plots/phase_diagram.py draws.
#include <string>

#include "analysis/bulk_flow_table.hpp"
#include "analysis/jamming_table.hpp"

namespace dilatant::analysis {

struct PhaseGrid {
  double mu0_max = 1.0;  // mu0 from 0 to mu0_max
  double mu0_step = 0.02;
  double phi_min = 0.50;  // phi from phi_min to phi_max
  double phi_max = 0.66;
  double phi_step = 0.002;
};

// Header "mu0,phi,regime,phi_max_bl,phi_rcp,margin_sigma,uncertain,source",
// one row per node, mu0 outer, phi inner; source is "bulk" or "sediment", and
// a bulk node has no margin_sigma (empty) and is not uncertain (as predict's
// --json). Nodes are computed as start + k step (no accumulated rounding), the
// last at or below the end. `bulk` nullptr: the sediment table alone.
std::string phase_diagram_csv(const JammingTable& table, const BulkFlowTable* bulk,
                              const PhaseGrid& grid);

}  // namespace dilatant::analysis
