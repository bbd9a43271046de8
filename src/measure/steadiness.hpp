#pragma once
// Is the averaging window steady? A run that is still accelerating (or slowing)
// past its transient gives a viscosity that depends on how long it ran. The test
// compares the wall speed's mean over the second half of the window with the
// first half's, each with its own block error (flow_series.hpp):
//
//     steady  <=>  |v2 - v1| <= max(3 sqrt(e1^2 + e2^2), 0.05 |v|)
//
// 3 sigma of the difference: no drift that the noise cannot explain; 5% of the
// mean: a drift smaller than that changes the viscosity by less than the
// resolution the flow curves are read at. Halves too short for block errors
// (fewer than 2 x kBlocks rows each) leave the answer unknown.
#include <vector>

#include "measure/flow_series.hpp"

namespace dilatant {

struct Drift {
  bool known = false;   // both halves long enough for an error bar
  bool steady = false;  // meaningful only if known
  double change = 0.0;  // (v2 - v1) / |v|, relative
  double error = 0.0;   // its 1-sigma error, relative
};

// Drift of the wall speed over the rows with strain > from.
Drift wall_speed_drift(const std::vector<FlowRow>& rows, double from);

// Drift of phi_bulk, the same test with a floor of 1% of phi instead of 5%
// (0.006 at phi 0.58, the resolution phi(J) curves are read at): under
// pressure control the rate is imposed and the box height is what may still
// move (docs/shear-cell.md "The pressure-imposed cell").
Drift volume_fraction_drift(const std::vector<FlowRow>& rows, double from);

}  // namespace dilatant
