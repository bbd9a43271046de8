#pragma once
// One flow curve from a rheometer export or a plain CSV/TSV table.
//
// The table is found by its header: the first line with at least two columns
// named shear rate, shear stress or viscosity (column_names.hpp); lines before
// it are metadata and are skipped. A units row right after the header (no
// numbers in the flow-curve columns, e.g. "[1/s]  [Pa]  [Pa·s]") gives the
// units of headings that have none. The separator is the header's (tab, ';',
// else ','); numbers may use a decimal comma. Data end at the first blank line
// after them; a second table after that is an error (one curve per file).
//
// Two of the three quantities are needed; the third follows from
// eta = tau / gamma_dot. When all three are given they must agree (median of
// eta * gamma_dot / tau within 10% of 1): a disagreement means a mislabelled
// unit. Values are converted to SI. Every value must be a finite number > 0
// (the analysis is in log-log), there must be at least 3 points, and the ramp
// variable (stress, or rate when no stress column) must be strictly monotonic,
// ascending or descending. Any violation is an InputError "file:line: problem".
#include <filesystem>
#include <vector>

#include "analysis/flow_curve.hpp"

namespace dilatant::analysis {

inline constexpr std::size_t kMinCurvePoints = 3;

// The points in ascending shear stress, in SI units.
std::vector<FlowPoint> read_flow_curve_file(const std::filesystem::path& file);

}  // namespace dilatant::analysis
