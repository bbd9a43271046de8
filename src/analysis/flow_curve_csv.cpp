#include "analysis/flow_curve_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "analysis/column_names.hpp"
#include "analysis/delimited_text.hpp"
#include "io/input_error.hpp"
#include "io/table_rows.hpp"

namespace dilatant::analysis {
namespace {

constexpr std::size_t kQuantities = 3;
// The median check of units: a mislabelled unit is a factor of 10 or more.
constexpr double kConsistencyTolerance = 0.10;

std::size_t index(Quantity q) { return static_cast<std::size_t>(q); }

struct Column {
  std::size_t field = 0;
  std::string heading;
  double to_si = 1.0;
};

struct Table {
  std::size_t header_line = 0;  // 1-based
  char separator = ',';
  std::size_t fields = 0;  // every row has as many (table_rows.hpp, rule 1)
  std::array<std::optional<Column>, kQuantities> columns;
};

class FileReader {
 public:
  explicit FileReader(const std::filesystem::path& file)
      : name_(file.string()), lines_(read_text_lines(file)) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", name_, line, what));
  }

  FlowCurveFile read() {
    if (std::all_of(lines_.begin(), lines_.end(), [](const auto& l) { return is_blank(l); }))
      fail(1, "empty file: expected a header naming shear rate, shear stress or viscosity");
    Table table = find_header();
    std::size_t next = table.header_line;  // 0-based index of the line after the header
    if (read_units_row(table, next)) ++next;
    for (std::size_t q = 0; q < kQuantities; ++q)
      if (table.columns[q]) convert_unit(table, static_cast<Quantity>(q));
    auto points = read_rows(table, next);
    check_consistency(table, points);
    for (const auto& v : viscosities_)
      check_implied_value(name_, v.line, "viscosity", v.written, "shear stress / shear rate",
                          v.implied, v.tolerance);
    return {in_ascending_stress(table, std::move(points)), dropped_.count(), dropped_.summary()};
  }

 private:
  // How many fields of the line name a flow-curve quantity.
  std::size_t recognised(const std::string& line) const {
    std::size_t n = 0;
    for (const auto& f : split_fields(line, detect_separator(line)))
      if (parse_heading(f).quantity) ++n;
    return n;
  }

  Table find_header() const {
    std::optional<std::size_t> header, single;
    for (std::size_t i = 0; i < lines_.size() && !header; ++i) {
      const auto n = recognised(lines_[i]);
      if (n >= 2) header = i;
      if (n == 1 && !single) single = i;
    }
    if (!header && !single) {
      for (std::size_t i = 0; i < lines_.size(); ++i)
        if (parse_number(split_fields(lines_[i], detect_separator(lines_[i])).front()))
          fail(i + 1, "data before any header naming shear rate, shear stress or viscosity");
      fail(1, "no header line naming shear rate, shear stress or viscosity");
    }
    const std::size_t at = header ? *header : *single;
    Table t;
    t.header_line = at + 1;
    t.separator = detect_separator(lines_[at]);
    const auto fields = split_fields(lines_[at], t.separator);
    t.fields = fields.size();
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const Heading h = parse_heading(fields[f]);
      if (!h.quantity) continue;
      auto& column = t.columns[index(*h.quantity)];
      if (column)
        fail(t.header_line, fmt::format("two {} columns ('{}' and '{}')",
                                        quantity_name(*h.quantity), column->heading, fields[f]));
      column = Column{f, fields[f], 1.0};
    }
    if (header) return t;
    for (std::size_t q = 0; q < kQuantities; ++q)
      if (t.columns[q])
        fail(t.header_line,
             fmt::format("missing column: found only {} ('{}'); need two of shear rate, "
                         "shear stress, viscosity",
                         quantity_name(static_cast<Quantity>(q)), t.columns[q]->heading));
    fail(t.header_line, "missing column");  // not reached
  }

  // A units row: the line after the header has no number in any flow-curve column.
  bool read_units_row(Table& t, std::size_t i) {
    if (i >= lines_.size() || is_blank(lines_[i])) return false;
    const auto fields = split_fields(lines_[i], t.separator);
    check_field_count(name_, i + 1, fields.size(), t.fields);
    for (const auto& c : t.columns) {
      if (!c) continue;
      if (fields[c->field].empty() || parse_number(fields[c->field])) return false;
    }
    for (auto& c : t.columns) {
      if (!c || !parse_heading(c->heading).unit.empty()) continue;
      c->heading += " " + fields[c->field];
      unit_row_[c->field] = unit_of_units_field(fields[c->field]);
      unit_line_ = i + 1;
    }
    return true;
  }

  void convert_unit(Table& t, Quantity q) {
    auto& c = *t.columns[index(q)];
    const auto from_row = unit_row_.find(c.field);
    const bool in_row = from_row != unit_row_.end();
    const std::string unit = in_row ? from_row->second : parse_heading(c.heading).unit;
    const auto factor = si_factor(q, unit);
    if (!factor)
      fail(in_row ? unit_line_ : t.header_line,
           fmt::format("column '{}': unknown unit '{}' for {} (known: {}; none = SI)", c.heading,
                       unit, quantity_name(q), known_units(q)));
    c.to_si = *factor;
  }

  // The value in SI, or nullopt when the row is dropped (table_rows.hpp, rule 2).
  std::optional<double> value(std::size_t line, const std::vector<std::string>& fields,
                              const Column& c) {
    const std::string& text = fields[c.field];
    const auto v = dropped_.positive(name_, line, c.heading, text, parse_number(text));
    if (!v) return std::nullopt;
    return *v * c.to_si;
  }

  // A line after the data that starts a second flow-curve table.
  bool is_second_table(const std::string& line) const { return recognised(line) >= 2; }

  std::vector<FlowPoint> read_rows(const Table& t, std::size_t first) {
    std::vector<FlowPoint> points;
    std::size_t i = first;
    for (; i < lines_.size() && !(is_blank(lines_[i]) && !points.empty()); ++i) {
      if (is_blank(lines_[i])) continue;
      const auto fields = split_fields(lines_[i], t.separator);
      check_field_count(name_, i + 1, fields.size(), t.fields);
      std::array<double, kQuantities> v{};
      bool kept = true;
      for (std::size_t q = 0; q < kQuantities; ++q) {
        if (!t.columns[q]) continue;
        const auto x = value(i + 1, fields, *t.columns[q]);
        kept = kept && x.has_value();
        if (x) v[q] = *x;
      }
      if (!kept) continue;
      FlowPoint p;
      p.line = i + 1;
      const auto has = [&](Quantity q) { return t.columns[index(q)].has_value(); };
      const double rate = v[index(Quantity::ShearRate)];
      const double stress = v[index(Quantity::ShearStress)];
      const double eta = v[index(Quantity::Viscosity)];
      p.shear_rate = has(Quantity::ShearRate) ? rate : stress / eta;
      p.shear_stress = has(Quantity::ShearStress) ? stress : eta * rate;
      p.viscosity = has(Quantity::Viscosity) ? eta : stress / rate;
      if (has(Quantity::ShearRate) && has(Quantity::ShearStress) && has(Quantity::Viscosity)) {
        const auto written = [&](Quantity q) {
          return written_resolution(fields[t.columns[index(q)]->field]);
        };
        viscosities_.push_back(
            {p.line, eta, stress / rate,
             implied_value_tolerance(written(Quantity::Viscosity), written(Quantity::ShearRate),
                                     written(Quantity::ShearStress))});
      }
      points.push_back(p);
    }
    for (; i < lines_.size(); ++i)
      if (is_second_table(lines_[i]))
        fail(i + 1, "a second flow-curve table: one curve per file (split the file)");
    if (points.size() < kMinCurvePoints)
      fail(points.empty() ? t.header_line : points.back().line,
           fmt::format("only {} data point{} after the header; a flow curve needs at least {}{}",
                       points.size(), points.size() == 1 ? "" : "s", kMinCurvePoints,
                       dropped_.count() == 0 ? "" : " (" + dropped_.summary() + ")"));
    return points;
  }

  void check_consistency(const Table& t, const std::vector<FlowPoint>& points) const {
    if (!std::all_of(t.columns.begin(), t.columns.end(), [](const auto& c) { return c; })) return;
    std::vector<double> ratio;
    for (const auto& p : points) ratio.push_back(p.viscosity * p.shear_rate / p.shear_stress);
    std::nth_element(ratio.begin(), ratio.begin() + static_cast<long>(ratio.size() / 2),
                     ratio.end());
    const double median = ratio[ratio.size() / 2];
    if (std::abs(median - 1.0) > kConsistencyTolerance)
      fail(unit_line_ ? unit_line_ : t.header_line,
           fmt::format("viscosity x shear rate / shear stress = {:.4g} (median over the file), "
                       "not 1: a unit in the header is wrong (e.g. mPa·s labelled Pa·s)",
                       median));
  }

  // The ramp variable must be strictly monotonic; the result ascends in stress.
  std::vector<FlowPoint> in_ascending_stress(const Table& t, std::vector<FlowPoint> points) const {
    const bool by_stress = t.columns[index(Quantity::ShearStress)].has_value();
    const auto ramp = [&](std::size_t k) {
      return by_stress ? points[k].shear_stress : points[k].shear_rate;
    };
    const std::string_view what = by_stress ? "shear stress" : "shear rate";
    // The ramp's direction is that of most of its steps (first to last on a
    // tie): one stray point, even the first, does not turn the ramp around.
    std::ptrdiff_t up = 0;
    for (std::size_t k = 1; k < points.size(); ++k) up += ramp(k) > ramp(k - 1) ? 1 : -1;
    const bool descending = up < 0 || (up == 0 && ramp(points.size() - 1) < ramp(0));
    const auto continues = [&](std::size_t a, std::size_t b) {
      return descending ? ramp(b) < ramp(a) : ramp(b) > ramp(a);
    };
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (continues(k - 1, k)) continue;
      // Points k-1 and k are out of order: the stray one is k-1 when the ramp
      // goes on without it (k-2 -> k) but not without k (k-1 -> k+1), as a
      // spike is; else k (a point that falls back, or repeats).
      const bool without_earlier = k < 2 || continues(k - 2, k);
      const bool without_later = k + 1 == points.size() || continues(k - 1, k + 1);
      const std::size_t bad = without_earlier && !without_later ? k - 1 : k;
      const auto neighbour = [&](std::size_t n) {
        return fmt::format("{:.6g} on line {}", ramp(n), points[n].line);
      };
      std::string around = bad > 0 ? "after " + neighbour(bad - 1) : "";
      if (bad + 1 < points.size())
        around += (around.empty() ? "before " : ", before ") + neighbour(bad + 1);
      fail(points[bad].line,
           fmt::format("{} {:.6g} breaks the {} ramp ({}): unsorted or repeated data", what,
                       ramp(bad), descending ? "descending" : "ascending", around));
    }
    if (descending) std::reverse(points.begin(), points.end());
    if (!by_stress)
      std::sort(points.begin(), points.end(),
                [](const auto& a, const auto& b) { return a.shear_stress < b.shear_stress; });
    return points;
  }

  std::string name_;
  std::vector<std::string> lines_;
  std::map<std::size_t, std::string> unit_row_;  // field -> unit from the units row
  std::size_t unit_line_ = 0;
  DroppedRows dropped_;
  // A row's viscosity against its stress / rate, checked after the units.
  struct ViscosityCheck {
    std::size_t line;
    double written, implied, tolerance;
  };
  std::vector<ViscosityCheck> viscosities_;
};

}  // namespace

FlowCurveFile read_flow_curve_file(const std::filesystem::path& file) {
  return FileReader(file).read();
}

}  // namespace dilatant::analysis
