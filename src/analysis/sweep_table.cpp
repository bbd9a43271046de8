// A simulation sweep's flowcurves.csv (analysis_input.hpp), grouped into one
// flow curve per (phi, mu0), or per (phi, sample) when the table labels its
// curves (a `sample` column, as `dilatant sweep` writes).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "analysis/analysis_input.hpp"
#include "analysis/delimited_text.hpp"
#include "io/input_error.hpp"
#include "io/table_rows.hpp"

namespace dilatant::analysis {
namespace {

using namespace std::string_view_literals;

constexpr std::array kRequired = {"phi"sv,       "mu0"sv,   "shear_stress"sv,
                                  "gamma_dot"sv, "valid"sv, "jammed"sv};

struct Columns {
  std::size_t phi, mu0, stress, rate, valid, jammed;
  std::optional<std::size_t> rate_err;
  std::optional<std::size_t> status;   // `dilatant sweep`: done | failed | pending
  std::optional<std::size_t> sample;   // `dilatant sweep`: the curve's label
  std::optional<std::size_t> eta;      // checked against shear_stress / gamma_dot
  std::optional<std::size_t> eta_err;  // FlowPoint::viscosity_err
  // `dilatant sweep`: rate, stress or pressure. A pressure-imposed point has no
  // fixed phi (it is measured): it belongs to mu(J), phi(J), not to a flow
  // curve eta(gamma_dot) at fixed phi, and is left out (docs/sweeps.md
  // "Pressure-imposed sweeps").
  std::optional<std::size_t> control;
  // `dilatant sweep`: the bulk fraction the point measured (FlowPoint::phi_measured).
  std::optional<std::size_t> phi_bulk;
  std::size_t count;
  std::optional<std::size_t> frac_bl;  // `dilatant sweep`: FlowPoint::frac_bl
};

class SweepReader {
 public:
  explicit SweepReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", name_, line, what));
  }

  Columns header(const std::string& line) const {
    const auto fields = split_fields(line, ',');
    auto find = [&](std::string_view name) -> std::optional<std::size_t> {
      const auto it = std::find(fields.begin(), fields.end(), name);
      if (it == fields.end()) return std::nullopt;
      return static_cast<std::size_t>(it - fields.begin());
    };
    for (const auto name : kRequired)
      if (!find(name))
        fail(1, fmt::format("missing column '{}' (a sweep table needs phi, mu0, shear_stress, "
                            "gamma_dot, valid, jammed)",
                            name));
    return Columns{*find("phi"),     *find("mu0"),    *find("shear_stress"), *find("gamma_dot"),
                   *find("valid"),   *find("jammed"), find("gamma_dot_err"), find("status"),
                   find("sample"),   find("eta"),     find("eta_err"),       find("control"),
                   find("phi_bulk"), fields.size(),   find("frac_bl")};
  }

  double number(std::size_t line, const std::vector<std::string>& f, std::size_t column,
                std::string_view name) const {
    const auto v = parse_number(f[column]);
    if (f[column].empty()) fail(line, fmt::format("column '{}': empty field", name));
    if (!v) fail(line, fmt::format("column '{}': '{}' is not a number", name, f[column]));
    if (!std::isfinite(*v))
      fail(line, fmt::format("column '{}': '{}' is not a finite number", name, f[column]));
    return *v;
  }

  bool boolean(std::size_t line, const std::vector<std::string>& f, std::size_t column,
               std::string_view name) const {
    std::string v = f[column];
    std::transform(v.begin(), v.end(), v.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail(line, fmt::format("column '{}': '{}' is not true or false", name, f[column]));
  }

  struct Row {
    double phi, mu0;
    std::string sample;
    FlowPoint point;
  };

  // A measured value that must be > 0, or nullopt: the row is dropped.
  std::optional<double> positive(std::size_t line, const std::vector<std::string>& f,
                                 std::size_t column, std::string_view name) {
    return dropped_.positive(name_, line, name, f[column], parse_number(f[column]));
  }

  // nullopt for a point of a sweep that has no result (status failed or
  // pending), or a row dropped for a missing, zero or negative value.
  std::optional<Row> row(std::size_t line, const std::string& text, const Columns& c) {
    const auto f = split_fields(text, ',');
    check_field_count(name_, line, f.size(), c.count);
    if (c.status && f[*c.status] != "done") return std::nullopt;
    if (c.control && f[*c.control] == "pressure") {
      ++pressure_rows_;
      return std::nullopt;
    }
    Row r{};
    r.phi = number(line, f, c.phi, "phi");
    if (!(r.phi > 0.0 && r.phi < 0.74))
      fail(line, fmt::format("column 'phi': {} must be in (0, 0.74)", r.phi));
    r.mu0 = number(line, f, c.mu0, "mu0");
    if (r.mu0 < 0.0) fail(line, fmt::format("column 'mu0': {} must be >= 0", r.mu0));
    r.sample = c.sample && !f[*c.sample].empty() ? f[*c.sample] : fmt::format("mu0={}", r.mu0);
    FlowPoint& p = r.point;
    p.line = line;
    p.valid = boolean(line, f, c.valid, "valid");
    p.jammed = boolean(line, f, c.jammed, "jammed");
    const auto stress = positive(line, f, c.stress, "shear_stress");
    // A jammed cell stopped: its rate 0 is a result, not a missing value.
    const bool stopped = p.jammed && parse_number(f[c.rate]) == 0.0;
    const auto rate = stopped ? std::optional(0.0) : positive(line, f, c.rate, "gamma_dot");
    if (!stress || !rate) return std::nullopt;
    p.shear_stress = *stress;
    p.shear_rate = *rate;
    if (c.rate_err && !f[*c.rate_err].empty()) {
      p.shear_rate_err = number(line, f, *c.rate_err, "gamma_dot_err");
      if (p.shear_rate_err < 0.0)
        fail(line, fmt::format("column 'gamma_dot_err': {} must be >= 0", p.shear_rate_err));
    }
    if (c.phi_bulk && !f[*c.phi_bulk].empty()) {
      p.phi_measured = number(line, f, *c.phi_bulk, "phi_bulk");
      if (!(p.phi_measured > 0.0 && p.phi_measured < 0.74))
        fail(line, fmt::format("column 'phi_bulk': {} must be in (0, 0.74)", p.phi_measured));
    }
    if (c.frac_bl && p.shear_rate > 0.0 && !f[*c.frac_bl].empty()) {
      p.frac_bl = number(line, f, *c.frac_bl, "frac_bl");
      if (!(p.frac_bl >= 0.0 && p.frac_bl <= 1.0))
        fail(line, fmt::format("column 'frac_bl': {} must be in [0, 1]", p.frac_bl));
    }
    if (c.eta_err && p.shear_rate > 0.0 && !f[*c.eta_err].empty()) {
      p.viscosity_err = number(line, f, *c.eta_err, "eta_err");
      if (p.viscosity_err < 0.0)
        fail(line, fmt::format("column 'eta_err': {} must be >= 0", p.viscosity_err));
    }
    p.viscosity = p.shear_rate > 0.0 ? p.shear_stress / p.shear_rate
                                     : std::numeric_limits<double>::quiet_NaN();
    if (c.eta && p.shear_rate > 0.0 && !f[*c.eta].empty()) {
      const double eta = number(line, f, *c.eta, "eta");
      check_implied_value(
          name_, line, "eta", eta, "shear_stress / gamma_dot", p.viscosity,
          implied_value_tolerance(written_resolution(f[*c.eta]), written_resolution(f[c.rate]),
                                  written_resolution(f[c.stress])));
    }
    return r;
  }

  const DroppedRows& dropped() const { return dropped_; }
  std::size_t pressure_rows() const { return pressure_rows_; }

 private:
  std::string name_;
  DroppedRows dropped_;
  std::size_t pressure_rows_ = 0;
};

}  // namespace

AnalysisInput read_sweep_table(const std::filesystem::path& table) {
  const std::string name = table.string();
  const auto lines = read_text_lines(table);
  SweepReader reader(name);
  if (lines.empty() || is_blank(lines[0])) reader.fail(1, "empty file: expected a header");
  const Columns columns = reader.header(lines[0]);

  AnalysisInput input;
  input.source = name;
  input.kind = InputKind::SweepTable;
  input.units = UnitSystem::Paper;
  std::map<std::pair<double, std::string>, std::size_t> curve_of;  // (phi, sample) -> curve
  std::size_t rows = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (is_blank(lines[i])) continue;
    ++rows;
    const auto parsed = reader.row(i + 1, lines[i], columns);
    if (!parsed) continue;
    const auto& r = *parsed;
    auto [it, added] = curve_of.try_emplace({r.phi, r.sample}, input.curves.size());
    if (added) {
      FlowCurve c;
      c.source = name;
      c.sample = r.sample;
      c.phi = r.phi;
      input.curves.push_back(std::move(c));
      if (std::find(input.samples.begin(), input.samples.end(), input.curves.back().sample) ==
          input.samples.end())
        input.samples.push_back(input.curves.back().sample);
    }
    input.curves[it->second].points.push_back(r.point);
  }
  if (rows == 0) reader.fail(1, "no data rows after the header");
  if (input.curves.empty() && reader.pressure_rows() > 0)
    reader.fail(
        1, fmt::format("no flow curve: the {} finished points are pressure-controlled "
                       "(control = pressure: phi measured, not fixed); plot mu_eff and phi_bulk "
                       "against viscous_number instead (docs/sweeps.md, \"Pressure-imposed "
                       "sweeps\")",
                       reader.pressure_rows()));
  input.note_dropped(name, reader.dropped().count(), reader.dropped().summary());
  if (input.curves.empty())
    reader.fail(1, reader.dropped().count() == 0 ? "no finished point (status done) in the table"
                                                 : "no point left: " + reader.dropped().summary());
  // Simulations are independent runs, listed in any order: sort by stress. Two
  // runs at the same stress of one curve would be two answers for one point.
  for (auto& c : input.curves) {
    std::sort(c.points.begin(), c.points.end(),
              [](const auto& a, const auto& b) { return a.shear_stress < b.shear_stress; });
    for (std::size_t k = 1; k < c.points.size(); ++k)
      if (c.points[k].shear_stress == c.points[k - 1].shear_stress)
        reader.fail(c.points[k].line,
                    fmt::format("shear_stress {} repeats line {} for phi {}, {} (one run "
                                "per point of a flow curve)",
                                c.points[k].shear_stress, c.points[k - 1].line, c.phi, c.sample));
  }
  return input;
}

}  // namespace dilatant::analysis
