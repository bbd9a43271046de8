// The row policy of every table reader; see table_rows.hpp.
#include "io/table_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant {
namespace {

// Lines named per kind in the summary: enough to find the pattern (every
// step start, a block of gaps), short enough for one line of the report.
constexpr std::size_t kLinesNamed = 5;

std::string plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

}  // namespace

void check_field_count(std::string_view source, std::size_t line, std::size_t fields,
                       std::size_t header_fields) {
  if (fields == header_fields) return;
  throw InputError(fmt::format(
      "{}:{}: {}, the header has {}: a malformed row (a separator too many or too few shifts "
      "the columns after it)",
      source, line, plural(fields, "field"), header_fields));
}

std::optional<double> DroppedRows::positive(std::string_view source, std::size_t line,
                                            std::string_view column, std::string_view text,
                                            std::optional<double> number) {
  std::optional<Why> why;
  if (text.empty() || (number && std::isnan(*number))) {
    why = Why::Missing;
  } else if (!number) {
    throw InputError(
        fmt::format("{}:{}: column '{}': '{}' is not a number", source, line, column, text));
  } else if (!std::isfinite(*number)) {
    throw InputError(
        fmt::format("{}:{}: column '{}': '{}' is not a finite number", source, line, column, text));
  } else if (*number <= 0.0) {
    why = Why::NotPositive;
  }
  if (!why) return number;
  if (lines_.empty() || lines_.back().first != line) lines_.emplace_back(line, *why);
  return std::nullopt;
}

void DroppedRows::repeated(std::size_t line) {
  if (lines_.empty() || lines_.back().first != line) lines_.emplace_back(line, Why::Repeated);
}

std::string DroppedRows::summary() const {
  if (lines_.empty()) return "";
  std::string kinds;
  for (const auto& [why, what] : {std::pair{Why::Missing, "missing value"},
                                  std::pair{Why::NotPositive, "zero or negative value"},
                                  std::pair{Why::Repeated, "repeated ramp value"}}) {
    std::vector<std::size_t> lines;
    for (const auto& [line, w] : lines_)
      if (w == why) lines.push_back(line);
    if (lines.empty()) continue;
    std::string named;
    for (std::size_t k = 0; k < std::min(lines.size(), kLinesNamed); ++k)
      named += fmt::format("{}{}", k == 0 ? "" : ", ", lines[k]);
    if (lines.size() > kLinesNamed) named += ", ...";
    kinds += fmt::format("{}{}: line{} {}", kinds.empty() ? "" : "; ", what,
                         lines.size() == 1 ? "" : "s", named);
  }
  return fmt::format("{} dropped ({})", plural(count(), "row"), kinds);
}

double written_resolution(std::string_view text) {
  std::string t(trim(text));
  if (!t.empty() && (t.front() == '+' || t.front() == '-')) t.erase(0, 1);
  std::replace(t.begin(), t.end(), ',', '.');  // a decimal comma
  double value = 0.0;
  std::from_chars(t.data(), t.data() + t.size(), value);
  const auto e = t.find_first_of("eE");
  const std::string mantissa = t.substr(0, e);
  int place = 0;  // the power of ten of the last significant digit
  if (e != std::string::npos)
    std::from_chars(t.data() + e + 1 + (t[e + 1] == '+'), t.data() + t.size(), place);
  if (const auto mark = mantissa.find('.'); mark != std::string::npos) {
    place -= static_cast<int>(mantissa.size() - mark - 1);
  } else {
    std::size_t end = mantissa.size();
    while (end > 1 && mantissa[end - 1] == '0') --end;
    place += static_cast<int>(mantissa.size() - end);
  }
  return value > 0.0 ? std::pow(10.0, place) / value : 1.0;
}

double implied_value_tolerance(double rx, double ry, double rz) {
  const double high = (1.0 + rx) * (1.0 + ry) / (1.0 - std::min(rz, 0.5)) - 1.0;
  const double low = 1.0 - (1.0 - std::min(rx, 1.0)) * (1.0 - std::min(ry, 1.0)) / (1.0 + rz);
  // The unit conversions (mPa s to Pa s) and the division add binary
  // rounding of order 1e-16: far below any written digit.
  return std::max(high, low) + 1e-12;
}

void check_implied_value(std::string_view source, std::size_t line, std::string_view name,
                         double written, std::string_view how, double implied, double tolerance) {
  const double deviation = std::abs(written / implied - 1.0);
  if (deviation <= tolerance) return;
  throw InputError(fmt::format(
      "{}:{}: {} {:.6g} disagrees with {} = {:.6g} by {:.3g}%, more than the {:.2g}% the "
      "written digits allow (a value typed or copied wrong, or columns mixed up)",
      source, line, name, written, how, implied, 100.0 * deviation, 100.0 * tolerance));
}

}  // namespace dilatant
