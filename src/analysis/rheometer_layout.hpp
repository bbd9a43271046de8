#pragma once
// Where the tables and steps of a rheometer export are (docs/analysis.md,
// "Rheometer exports"). A file of one measurement is metadata lines and one
// table; a file of a whole procedure holds one table per step, and each vendor
// marks the steps its own way:
//
//   TA TRIOS (.txt, .csv)     "[step]", a title line ("Flow sweep - 3"), the
//                             step's header, a units row, its data, a blank
//                             line; "[File Parameters]"-like sections before
//   Anton Paar RheoCompass    "Interval and data points:  2  21" (German
//                             "Intervall und Datenpunkte:", French "Intervalle
//                             et points de données:"), then the interval's
//                             "Interval data:" header, an empty row, units
//   Malvern rSpace            one table whose first column, "Action Name",
//                             names each row's step ("Flow Curve Up", ...)
//   plain tables              a header; a blank line then another header
//                             starts another table (another step)
//
// This file finds those tables and steps; it does not read their numbers
// (flow_curve_csv.hpp) nor decide what kind of step each is (step_kind.hpp).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dilatant::analysis {

// One table: a header, an optional units row, its rows. Line numbers are
// 1-based, as messages give them.
struct RheometerTable {
  std::size_t header_line = 0;
  std::optional<std::size_t> units_line;
  char separator = ',';
  std::vector<std::string> headings;  // the header's fields
  std::vector<std::string> units;     // the units row's fields; empty when none
  // The column whose text names each row's step (Malvern's "Action Name").
  std::optional<std::size_t> step_column;
};

// One step: a table, or the rows of one step of a table with a step column.
struct RheometerStepRows {
  std::string name;                // as the export names it; "" when it does not
  std::size_t first_line = 0;      // its marker, else its header, else its first row
  std::size_t table = 0;           // index into RheometerLayout::tables
  std::vector<std::size_t> lines;  // its data rows (1-based), blank lines left out
};

struct RheometerLayout {
  std::vector<RheometerTable> tables;
  std::vector<RheometerStepRows> steps;  // in file order
  // A line with exactly one flow-curve heading, when no table was found: the
  // reader's message says which column is missing.
  std::optional<std::size_t> single_heading_line;
};

// Finds the tables and steps of `lines` (the file's lines, read_text_lines()).
// Every row of a table must have as many fields as its header (InputError
// "source:line: ..." otherwise, io/table_rows.hpp rule 1).
RheometerLayout find_rheometer_layout(std::string_view source,
                                      const std::vector<std::string>& lines);

// How many fields of a header line name a flow-curve quantity (column_names.hpp).
std::size_t flow_headings(const std::vector<std::string>& fields);

}  // namespace dilatant::analysis
