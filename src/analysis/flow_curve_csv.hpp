#pragma once
// One flow curve from one table (or one step of a table) of a rheometer export
// or a plain CSV/TSV file; rheometer_layout.hpp finds the tables and steps,
// rheometer_file.hpp puts the two together.
//
// The columns are recognised by name (column_names.hpp): two of shear rate,
// shear stress and viscosity are needed; the third follows from
// eta = tau / gamma_dot. Units come from the heading or, for headings without
// one, from the table's units row; values are converted to SI. Numbers use the
// file's decimal mark, '.' or ',' (decimal_mark()): decided once per file, not
// guessed per row. When all three quantities are given they must agree
// (median of eta * gamma_dot / tau within 10% of 1): a disagreement means a
// mislabelled unit; then each row's viscosity must agree with its stress /
// rate within what the written digits allow (io/table_rows.hpp, rule 4). Rows
// follow the policy of every table (io/table_rows.hpp): a row with a missing,
// zero or negative value is dropped and counted (the analysis is in log-log;
// instruments write zero stress at a step's start). Any other problem is an
// InputError "file:line: problem".
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/flow_curve.hpp"
#include "analysis/rheometer_layout.hpp"
#include "io/table_rows.hpp"

namespace dilatant::analysis {

inline constexpr std::size_t kMinCurvePoints = 3;

struct FlowCurveFile {
  std::vector<FlowPoint> points;  // SI units; ascending shear stress once ordered
  std::size_t dropped_rows = 0;   // rows with a missing, zero or negative value
  std::string dropped;            // DroppedRows::summary(): which lines and why; "" if none
  bool ramp_in_stress = true;     // the ramp variable: stress, or rate when no stress column
  DroppedRows drops;              // what dropped_rows and dropped summarise
};

// The points of `rows` (1-based lines of `lines`) of `table`, in file order.
FlowCurveFile read_flow_table(std::string_view source, const std::vector<std::string>& lines,
                              const RheometerTable& table, const std::vector<std::size_t>& rows,
                              char decimal_mark);

// Drops (and counts, in `drops`) a point whose ramp value repeats the previous
// point's exactly, as read: an export that writes set points with too few
// digits ("0.18" twice, TA TRIOS at low stress) gives two points no abscissa
// can separate; a value that goes back is still the ramp's error below.
void drop_repeated_ramp_values(FlowCurveFile& curve);

// Checks that the ramp variable is strictly monotonic, ascending or
// descending (a point that breaks it is named), and orders the points by
// ascending stress. Needs at least 2 points.
void order_flow_curve(std::string_view source, FlowCurveFile& curve);

// The file's decimal mark: '.' when its tables are comma-separated; else ','
// when a value of a flow-curve column is written with a decimal comma ("1,5",
// "2,21E+04"); else '.'.
char decimal_mark(const std::vector<std::string>& lines, const RheometerLayout& layout);

}  // namespace dilatant::analysis
