#include "analysis/rheometer_layout.hpp"

#include <algorithm>

#include "analysis/column_names.hpp"
#include "analysis/delimited_text.hpp"
#include "io/table_rows.hpp"
#include "io/text.hpp"

namespace dilatant::analysis {
namespace {

bool all_empty(const std::vector<std::string>& fields) {
  return std::all_of(fields.begin(), fields.end(), [](const auto& f) { return f.empty(); });
}

// "[step]", "[File Parameters]": TRIOS's section lines (one bracket pair: a
// units row "[1/s];[Pa]" has two).
bool is_section(std::string_view trimmed) {
  return trimmed.size() >= 2 && trimmed.front() == '[' && trimmed.back() == ']' &&
         trimmed.find(']') == trimmed.size() - 1;
}

// RheoCompass's "Interval and data points:  2  21" (and its German and French
// forms): the interval's number, or nullopt for any other line.
std::optional<std::string> interval_marker(const std::vector<std::string>& f) {
  if (f.size() < 2 || f[1].empty()) return std::nullopt;
  const std::string label = lower_case(f[0]);
  if (!label.starts_with("interval") || !label.ends_with(':')) return std::nullopt;
  if (!std::all_of(f[1].begin(), f[1].end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return f[1];
}

// RheoCompass's "Result:  Flow Curve 1" names the measurement its intervals belong to.
std::optional<std::string> result_name(const std::vector<std::string>& f) {
  if (f.size() < 2 || f[1].empty()) return std::nullopt;
  const std::string label = lower_case(f[0]);
  if (label == "result:" || label == "r\xC3\xA9sultat:" || label == "resultat:" ||
      label == "ergebnis:")
    return f[1];
  return std::nullopt;
}

bool has_number(const std::vector<std::string>& f) {
  return std::any_of(f.begin(), f.end(), [](const auto& x) { return parse_number(x).has_value(); });
}

// The header of a TRIOS step's table, which may name no flow-curve column (an
// amplitude sweep's): flow-curve headings, the LIMS export's "Variables" line,
// or three or more names and no number (not "Number of points  17").
bool is_step_header(const std::vector<std::string>& f) {
  if (flow_headings(f) >= 2 || (!f.empty() && lower_case(f[0]) == "variables")) return true;
  const auto named = std::count_if(f.begin(), f.end(), [](const auto& x) { return !x.empty(); });
  return named >= 3 && !has_number(f);
}

// A metadata line ("Test:  B", "Projet:  x"): its first field is a label.
bool is_label_line(const std::vector<std::string>& f) {
  return !f.empty() && f[0].size() > 1 && f[0].back() == ':';
}

std::vector<std::string> fields_of(const std::string& line) {
  return split_fields(line, detect_separator(line));
}

class LayoutFinder {
 public:
  LayoutFinder(std::string_view source, const std::vector<std::string>& lines)
      : source_(source), lines_(lines) {}

  RheometerLayout find() {
    enum class Expect { Nothing, Title, Header } expect = Expect::Nothing;
    for (std::size_t i = 0; i < lines_.size();) {
      const std::string_view t = trim(lines_[i]);
      if (t.empty()) {
        ++i;
        continue;
      }
      if (is_section(t)) {
        const bool step = lower_case(t) == "[step]";
        interval_ = false;
        expect = step ? Expect::Title : Expect::Nothing;
        marker_ = step ? i + 1 : 0;
        name_.clear();
        ++i;
        continue;
      }
      const auto fields = fields_of(lines_[i]);
      // TRIOS's LIMS export names the step on a "Step name" line.
      if (expect != Expect::Nothing && fields.size() >= 2 && lower_case(fields[0]) == "step name") {
        name_ = fields[1];
        expect = Expect::Header;
        ++i;
        continue;
      }
      if (expect == Expect::Title && !is_step_header(fields)) {
        // TRIOS's text export: the line after "[step]" names it ("Flow sweep - 3").
        const auto named =
            std::find_if(fields.begin(), fields.end(), [](const auto& f) { return !f.empty(); });
        name_ = named == fields.end() ? "" : *named;
        expect = Expect::Header;
        ++i;
        continue;
      }
      if (const auto n = interval_marker(fields)) {
        marker_ = i + 1;
        name_ = (result_.empty() ? "" : result_ + ", ") + "interval " + *n;
        interval_ = true;
        expect = Expect::Header;
        ++i;
        continue;
      }
      if (const auto r = result_name(fields)) result_ = *r;
      const std::size_t recognised = flow_headings(fields);
      // After "[step]" and its title the header follows; after an interval
      // marker, metadata ("Profile:") may come first, then "Interval data:".
      const bool header =
          recognised >= 2 ||
          (expect != Expect::Nothing &&
           (interval_ ? lower_case(fields[0]).starts_with("interval") : is_step_header(fields)));
      if (header) {
        i = read_table(i);
        expect = Expect::Nothing;
        interval_ = false;
        marker_ = 0;
        name_.clear();
        continue;
      }
      if (recognised == 1 && !layout_.single_heading_line) layout_.single_heading_line = i + 1;
      ++i;
    }
    return std::move(layout_);
  }

 private:
  // A line that cannot be a row of the table above it: the table has ended.
  bool ends_table(std::string_view trimmed, const std::vector<std::string>& own_fields) const {
    return is_section(trimmed) || interval_marker(own_fields) || is_label_line(own_fields) ||
           flow_headings(own_fields) >= 2;
  }

  // A units row names no number where the table's numbers go: in every
  // flow-curve column (or, in a table without such columns, anywhere).
  static bool is_units_row(const RheometerTable& t, const std::vector<std::string>& f) {
    bool flow_table = false, number = false, text = false;
    for (std::size_t k = 0; k < f.size(); ++k) {
      const bool is_number = parse_number(f[k]).has_value();
      if (parse_heading(t.headings[k]).quantity) {
        flow_table = true;
        if (f[k].empty() || is_number) return false;
      }
      number = number || is_number;
      text = text || (!f[k].empty() && !is_number);
    }
    return flow_table || (text && !number);
  }

  std::size_t read_table(std::size_t header) {
    RheometerTable t;
    t.header_line = header + 1;
    t.separator = detect_separator(lines_[header]);
    t.headings = split_fields(lines_[header], t.separator);
    for (std::size_t k = 0; k < t.headings.size(); ++k)
      if (names_step_column(t.headings[k])) t.step_column = k;
    std::vector<std::size_t> rows;
    std::size_t j = header + 1;
    for (; j < lines_.size(); ++j) {
      const std::string_view trimmed = trim(lines_[j]);
      const auto f = split_fields(lines_[j], t.separator);
      // A blank line ends the table once it has rows; before them, and empty
      // fields there, is RheoCompass's empty row between header and units. A
      // row of empty fields among the data is a row (dropped: rule 2).
      if (trimmed.empty() && !rows.empty()) break;
      if (trimmed.empty() || (rows.empty() && all_empty(f))) continue;
      if (ends_table(trimmed, fields_of(lines_[j]))) break;
      check_field_count(source_, j + 1, f.size(), t.headings.size());
      // Before the data and the units row, a row without numbers is the units
      // row, or a second header line (RheoCompass's "Sinusoïdes" over its
      // oscillation columns). After the units row it is a row (RheoCompass's
      // "1 (invalid)" points: dropped as missing values, and counted).
      if (rows.empty() && !t.units_line && !has_number(f)) {
        if (!t.units_line && is_units_row(t, f)) {
          t.units_line = j + 1;
          t.units = f;
        }
        continue;
      }
      rows.push_back(j + 1);
    }
    const std::size_t index = layout_.tables.size();
    add_steps(t, index, rows);
    layout_.tables.push_back(std::move(t));
    return j;
  }

  // One step per table, or with a step column one per run of rows naming the same step.
  void add_steps(const RheometerTable& t, std::size_t table, const std::vector<std::size_t>& rows) {
    if (!t.step_column || rows.empty()) {
      layout_.steps.push_back({name_, marker_ ? marker_ : t.header_line, table, rows});
      return;
    }
    for (const std::size_t line : rows) {
      const std::string step = split_fields(lines_[line - 1], t.separator)[*t.step_column];
      auto& steps = layout_.steps;
      if (steps.empty() || steps.back().table != table || steps.back().name != step)
        steps.push_back({step, line, table, {}});
      steps.back().lines.push_back(line);
    }
  }

  std::string_view source_;
  const std::vector<std::string>& lines_;
  RheometerLayout layout_;
  std::size_t marker_ = 0;  // the line of the pending step's marker
  std::string name_;        // the pending step's name
  std::string result_;      // RheoCompass's current result
  bool interval_ = false;   // the pending step's marker is an interval line
};

}  // namespace

std::size_t flow_headings(const std::vector<std::string>& fields) {
  return static_cast<std::size_t>(std::count_if(fields.begin(), fields.end(), [](const auto& f) {
    return parse_heading(f).quantity.has_value();
  }));
}

RheometerLayout find_rheometer_layout(std::string_view source,
                                      const std::vector<std::string>& lines) {
  return LayoutFinder(source, lines).find();
}

}  // namespace dilatant::analysis
