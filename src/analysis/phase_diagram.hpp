#pragma once
// The paper's phase diagram (Fernandez et al. 2013, Fig. 4) drawn from our
// jamming table: the regime predict_regime assigns at every node of a grid
// of (mu0, phi), as the CSV that python/dilatant/plots/phase_diagram.py draws.
#include <string>

#include "analysis/jamming_table.hpp"

namespace dilatant::analysis {

struct PhaseGrid {
  double mu0_max = 1.0;  // mu0 from 0 to mu0_max
  double mu0_step = 0.02;
  double phi_min = 0.50;  // phi from phi_min to phi_max
  double phi_max = 0.66;
  double phi_step = 0.002;
};

// Header "mu0,phi,regime,phi_max_bl,phi_rcp,margin_sigma,uncertain", one row
// per node, mu0 outer, phi inner. Nodes are computed as start + k step (no
// accumulated rounding), the last at or below the end.
std::string phase_diagram_csv(const JammingTable& table, const PhaseGrid& grid);

}  // namespace dilatant::analysis
