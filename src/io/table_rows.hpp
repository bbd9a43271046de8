#pragma once
// The row policy of every reader of a user's table (docs/analysis.md "Rows of
// a table"): rheometer exports, sweep tables, jamming tables, particle files.
//
//   1. A row whose field count differs from its header's is a malformed file:
//      bad input (exit 2) naming the line. A field too many or too few shifts
//      every column after it, so no value of that row can be trusted.
//   2. In a well-formed table, a measured value that must be > 0 (a shear
//      stress, rate or viscosity) and is missing (an empty field, NaN), zero
//      or negative drops its row, counted and reported. Instruments write such
//      rows where nothing was measured: zero stress at the start of a step, a
//      gap where a reading failed.
//   3. Anything else that cannot be read (text where a number belongs, an
//      infinite number, a parameter out of its range) is bad input naming the
//      line: that is not a reading the instrument missed but a file that says
//      something else than the reader expects. Tables that define a model or
//      a scene (jamming tables, particles) have no measured values: every row
//      counts, so every bad value is bad input.
//   4. A value that a row gives twice (viscosity, and shear stress / shear
//      rate) must agree within what the written digits allow
//      (implied_value_tolerance), else bad input naming the line.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dilatant {

// Rule 1: InputError "source:line: 3 fields, the header has 4: ..." unless
// `fields` equals `header_fields`.
void check_field_count(std::string_view source, std::size_t line, std::size_t fields,
                       std::size_t header_fields);

// Rule 2: the rows a reader dropped, and why, for the report.
class DroppedRows {
 public:
  // The value of a measured field that must be > 0, or nullopt when its row is
  // dropped (then recorded here, once per line). `number` is `text` read by the
  // reader's own number syntax (nullopt when it is none): text that is not a
  // number, or an infinite one, is an InputError (rule 3).
  std::optional<double> positive(std::string_view source, std::size_t line, std::string_view column,
                                 std::string_view text, std::optional<double> number);
  // A row of a flow curve whose ramp value (stress, or rate) repeats the
  // previous row's as written: an abscissa cannot separate them (an export
  // writing set points with too few digits, "0.18, 0.18"). Rule 2 as well.
  void repeated(std::size_t line);
  std::size_t count() const { return lines_.size(); }
  // "2 rows dropped (missing value: line 7; zero or negative value: line 9;
  // repeated ramp value: line 12)",
  // naming at most a few lines of each kind; "" when none.
  std::string summary() const;

 private:
  enum class Why { Missing, NotPositive, Repeated };
  std::vector<std::pair<std::size_t, Why>> lines_;
};

// One unit of the last written digit of a number, relative to the number:
// "12.5" -> 0.1 / 12.5, "1,5e3" -> 100 / 1500. Trailing zeros of an integer
// ("700") are not taken as significant (100 / 700): they may be rounding.
double written_resolution(std::string_view text);

// Rule 4: how far x * y / z, each read from written text, may lie from 1 when
// the instrument computed them from its exact values (x * y = z): each written
// value is within one unit of its last digit of the instrument's value, since
// exports round or truncate, so the ratio lies in
// [(1 - rx)(1 - ry)/(1 + rz), (1 + rx)(1 + ry)/(1 - rz)]. Returns the larger
// distance of that interval from 1.
double implied_value_tolerance(double rx, double ry, double rz);

// Rule 4: InputError "source:line: <name> <written> disagrees with <how>
// = <implied> by <d>%, more than the <tolerance>% its written digits allow"
// when |written / implied - 1| exceeds `tolerance`.
void check_implied_value(std::string_view source, std::size_t line, std::string_view name,
                         double written, std::string_view how, double implied, double tolerance);

}  // namespace dilatant
