#pragma once
// A small comma-separated table of numbers with a header line, as the data
// files shipped in data/ are written (data/jamming/*.csv): columns looked up
// by name, cells read as finite numbers, every error naming the source and
// its line. Blank lines are skipped; a row with another field count than the
// header is an error (io/table_rows.hpp, rule 1). Its tables define a model,
// not measurements: every value must be read, none is dropped.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dilatant::analysis {

class NumericCsv {
 public:
  // `lines` are the file's lines (header first); `source` names the file in
  // messages. Throws InputError when there is no header.
  NumericCsv(std::vector<std::string> lines, std::string source);
  static NumericCsv from_text(std::string_view text, std::string source);

  // Index of a required column; throws InputError naming it and `needs` (the
  // list of columns the reader requires) when it is missing.
  std::size_t column(std::string_view name, std::string_view needs) const;
  // Index of an optional column, empty when the header has none.
  std::optional<std::size_t> find_column(std::string_view name) const;

  std::size_t rows() const { return rows_.size(); }
  // Line number of row r in the source (1-based, header is line 1).
  std::size_t line_of(std::size_t r) const { return line_numbers_[r]; }
  // Cell (r, c) as a finite number; an empty cell is `empty_value` when it is
  // given, an error otherwise.
  double number(std::size_t r, std::size_t c, std::string_view name) const;
  double number_or(std::size_t r, std::size_t c, std::string_view name, double empty_value) const;
  // Cell (r, c) as text ("" when the row is short).
  std::string text(std::size_t r, std::size_t c) const;
  // InputError with "source:line: what" for row r.
  [[noreturn]] void fail(std::size_t r, const std::string& what) const;
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> header_;
  std::size_t header_line_ = 1;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> line_numbers_;
};

}  // namespace dilatant::analysis
