#include "analysis/numeric_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/delimited_text.hpp"
#include "io/input_error.hpp"
#include "io/table_rows.hpp"

namespace dilatant::analysis {

NumericCsv::NumericCsv(std::vector<std::string> lines, std::string source)
    : source_(std::move(source)) {
  std::size_t k = 0;
  while (k < lines.size() && is_blank(lines[k])) ++k;
  if (k == lines.size()) throw InputError(source_ + ": empty table (no header line)");
  header_ = split_fields(lines[k], ',');
  header_line_ = k + 1;
  for (++k; k < lines.size(); ++k) {
    if (is_blank(lines[k])) continue;
    rows_.push_back(split_fields(lines[k], ','));
    check_field_count(source_, k + 1, rows_.back().size(), header_.size());
    line_numbers_.push_back(k + 1);
  }
}

NumericCsv NumericCsv::from_text(std::string_view text, std::string source) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(start, end - start));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return NumericCsv(std::move(lines), std::move(source));
}

std::size_t NumericCsv::column(std::string_view name, std::string_view needs) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end())
    throw InputError(
        fmt::format("{}:{}: no column {} (needs {})", source_, header_line_, name, needs));
  return static_cast<std::size_t>(it - header_.begin());
}

std::optional<std::size_t> NumericCsv::find_column(std::string_view name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header_.begin());
}

std::string NumericCsv::text(std::size_t r, std::size_t c) const {
  return c < rows_[r].size() ? rows_[r][c] : std::string();
}

void NumericCsv::fail(std::size_t r, const std::string& what) const {
  throw InputError(fmt::format("{}:{}: {}", source_, line_numbers_[r], what));
}

double NumericCsv::number(std::size_t r, std::size_t c, std::string_view name) const {
  const std::string t = text(r, c);
  const auto v = parse_number(t);
  if (!v || !std::isfinite(*v)) fail(r, fmt::format("{} = \"{}\" is not a finite number", name, t));
  return *v;
}

double NumericCsv::number_or(std::size_t r, std::size_t c, std::string_view name,
                             double empty_value) const {
  return text(r, c).empty() ? empty_value : number(r, c, name);
}

}  // namespace dilatant::analysis
