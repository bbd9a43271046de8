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
// unit; then each row's viscosity must agree with its stress / rate within
// what the written digits allow (io/table_rows.hpp, rule 4). Values are
// converted to SI. Rows follow the policy of every table (io/table_rows.hpp):
// a row with another field count than the header is an error; a row with a
// missing, zero or negative value is dropped and counted (the analysis is in
// log-log; instruments write zero stress at a step's start). There must be at
// least 3 points, and the ramp variable (stress, or rate when no stress
// column) must be strictly monotonic, ascending or descending; a point that
// breaks it is named. Any violation is an InputError "file:line: problem".
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/flow_curve.hpp"

namespace dilatant::analysis {

inline constexpr std::size_t kMinCurvePoints = 3;

struct FlowCurveFile {
  std::vector<FlowPoint> points;  // ascending shear stress, SI units
  std::size_t dropped_rows = 0;   // rows with a missing, zero or negative value
  std::string dropped;            // DroppedRows::summary(): which lines and why; "" if none
};

FlowCurveFile read_flow_curve_file(const std::filesystem::path& file);

}  // namespace dilatant::analysis
