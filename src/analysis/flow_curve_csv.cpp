#include "analysis/flow_curve_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
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
  std::string heading;  // with the units row's unit appended, for messages
  double to_si = 1.0;
};

class TableReader {
 public:
  TableReader(std::string_view source, const std::vector<std::string>& lines,
              const RheometerTable& table, char mark)
      : source_(source), lines_(lines), table_(table), mark_(mark) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", source_, line, what));
  }

  FlowCurveFile read(const std::vector<std::size_t>& rows) {
    find_columns();
    FlowCurveFile out;
    out.points = read_rows(rows);
    check_consistency(out.points);
    for (const auto& v : viscosities_)
      check_implied_value(source_, v.line, "viscosity", v.written, "shear stress / shear rate",
                          v.implied, v.tolerance);
    out.dropped_rows = dropped_.count();
    out.dropped = dropped_.summary();
    out.drops = dropped_;
    out.ramp_in_stress = has(Quantity::ShearStress);
    return out;
  }

 private:
  bool has(Quantity q) const { return columns_[index(q)].has_value(); }

  void find_columns() {
    const auto& h = table_.headings;
    for (std::size_t f = 0; f < h.size(); ++f) {
      const Heading heading = parse_heading(h[f]);
      if (!heading.quantity) continue;
      auto& column = columns_[index(*heading.quantity)];
      if (column)
        fail(table_.header_line,
             fmt::format("two {} columns ('{}' and '{}')", quantity_name(*heading.quantity),
                         column->heading, h[f]));
      const bool unit_in_row = heading.unit.empty() && !table_.units.empty();
      const std::string unit = unit_in_row ? unit_of_units_field(table_.units[f]) : heading.unit;
      const auto factor = si_factor(*heading.quantity, unit);
      const std::string name = unit_in_row ? h[f] + " " + table_.units[f] : h[f];
      if (!factor)
        fail(unit_in_row ? *table_.units_line : table_.header_line,
             fmt::format("column '{}': unknown unit '{}' for {} (known: {}; none = SI)", name, unit,
                         quantity_name(*heading.quantity), known_units(*heading.quantity)));
      column = Column{f, name, *factor};
      if (unit_in_row) unit_line_ = *table_.units_line;
    }
    const auto found = static_cast<std::size_t>(
        std::count_if(columns_.begin(), columns_.end(), [](const auto& c) { return c; }));
    if (found >= 2) return;
    for (std::size_t q = 0; q < kQuantities; ++q)
      if (columns_[q])
        fail(table_.header_line,
             fmt::format("missing column: found only {} ('{}'); need two of shear rate, "
                         "shear stress, viscosity",
                         quantity_name(static_cast<Quantity>(q)), columns_[q]->heading));
    fail(table_.header_line, "missing column: no shear rate, shear stress or viscosity");
  }

  // The value in SI, or nullopt when the row is dropped (table_rows.hpp, rule 2).
  std::optional<double> value(std::size_t line, const std::vector<std::string>& fields,
                              const Column& c) {
    const std::string& text = fields[c.field];
    const auto v = dropped_.positive(source_, line, c.heading, text, parse_number(text, mark_));
    if (!v) return std::nullopt;
    return *v * c.to_si;
  }

  std::vector<FlowPoint> read_rows(const std::vector<std::size_t>& rows) {
    std::vector<FlowPoint> points;
    for (const std::size_t line : rows) {
      const auto fields = split_fields(lines_[line - 1], table_.separator);
      std::array<double, kQuantities> v{};
      bool kept = true;
      for (std::size_t q = 0; q < kQuantities; ++q) {
        if (!columns_[q]) continue;
        const auto x = value(line, fields, *columns_[q]);
        kept = kept && x.has_value();
        if (x) v[q] = *x;
      }
      if (!kept) continue;
      FlowPoint p;
      p.line = line;
      const double rate = v[index(Quantity::ShearRate)];
      const double stress = v[index(Quantity::ShearStress)];
      const double eta = v[index(Quantity::Viscosity)];
      p.shear_rate = has(Quantity::ShearRate) ? rate : stress / eta;
      p.shear_stress = has(Quantity::ShearStress) ? stress : eta * rate;
      p.viscosity = has(Quantity::Viscosity) ? eta : stress / rate;
      if (has(Quantity::ShearRate) && has(Quantity::ShearStress) && has(Quantity::Viscosity)) {
        const auto written = [&](Quantity q) {
          return written_resolution(fields[columns_[index(q)]->field]);
        };
        viscosities_.push_back(
            {p.line, eta, stress / rate,
             implied_value_tolerance(written(Quantity::Viscosity), written(Quantity::ShearRate),
                                     written(Quantity::ShearStress))});
      }
      points.push_back(p);
    }
    return points;
  }

  void check_consistency(const std::vector<FlowPoint>& points) const {
    if (points.empty() || !has(Quantity::ShearRate) || !has(Quantity::ShearStress) ||
        !has(Quantity::Viscosity))
      return;
    std::vector<double> ratio;
    for (const auto& p : points) ratio.push_back(p.viscosity * p.shear_rate / p.shear_stress);
    std::nth_element(ratio.begin(), ratio.begin() + static_cast<long>(ratio.size() / 2),
                     ratio.end());
    const double median = ratio[ratio.size() / 2];
    if (std::abs(median - 1.0) > kConsistencyTolerance)
      fail(unit_line_ ? unit_line_ : table_.header_line,
           fmt::format("viscosity x shear rate / shear stress = {:.4g} (median over the table), "
                       "not 1: a unit in the header is wrong (e.g. mPa·s labelled Pa·s)",
                       median));
  }

  std::string_view source_;
  const std::vector<std::string>& lines_;
  const RheometerTable& table_;
  char mark_;
  std::array<std::optional<Column>, kQuantities> columns_;
  std::size_t unit_line_ = 0;
  DroppedRows dropped_;
  // A row's viscosity against its stress / rate, checked after the units.
  struct ViscosityCheck {
    std::size_t line;
    double written, implied, tolerance;
  };
  std::vector<ViscosityCheck> viscosities_;
};

// A value written with a decimal comma: a number with one ',' and no '.'.
bool has_decimal_comma(std::string_view text) {
  return text.find(',') != std::string_view::npos && parse_number(text, ',').has_value();
}

}  // namespace

FlowCurveFile read_flow_table(std::string_view source, const std::vector<std::string>& lines,
                              const RheometerTable& table, const std::vector<std::size_t>& rows,
                              char decimal_mark) {
  return TableReader(source, lines, table, decimal_mark).read(rows);
}

char decimal_mark(const std::vector<std::string>& lines, const RheometerLayout& layout) {
  for (const auto& step : layout.steps) {
    const RheometerTable& t = layout.tables[step.table];
    if (t.separator == ',') return '.';
    for (const std::size_t line : step.lines) {
      const auto fields = split_fields(lines[line - 1], t.separator);
      for (std::size_t f = 0; f < fields.size(); ++f)
        if (parse_heading(t.headings[f]).quantity && has_decimal_comma(fields[f])) return ',';
    }
  }
  return '.';
}

void drop_repeated_ramp_values(FlowCurveFile& curve) {
  const auto ramp = [&](const FlowPoint& p) {
    return curve.ramp_in_stress ? p.shear_stress : p.shear_rate;
  };
  std::vector<FlowPoint> kept;
  for (const FlowPoint& p : curve.points) {
    if (!kept.empty() && ramp(p) == ramp(kept.back())) {
      curve.drops.repeated(p.line);
      continue;
    }
    kept.push_back(p);
  }
  curve.points = std::move(kept);
  curve.dropped_rows = curve.drops.count();
  curve.dropped = curve.drops.summary();
}

void order_flow_curve(std::string_view source, FlowCurveFile& curve) {
  auto& points = curve.points;
  const bool by_stress = curve.ramp_in_stress;
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
    throw InputError(
        fmt::format("{}:{}: {} {:.6g} breaks the {} ramp ({}): unsorted or repeated "
                    "data",
                    source, points[bad].line, what, ramp(bad),
                    descending ? "descending" : "ascending", around));
  }
  if (descending) std::reverse(points.begin(), points.end());
  if (!by_stress)
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& b) { return a.shear_stress < b.shear_stress; });
}

}  // namespace dilatant::analysis
