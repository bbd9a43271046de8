#include "analysis/jamming_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/delimited_text.hpp"
#include "dilatant/jamming_table_data.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {

namespace {

std::vector<std::string> lines_of(std::string_view text) {
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
  return lines;
}

}  // namespace

JammingTable JammingTable::parse(std::string_view csv, const std::string& source) {
  const auto lines = lines_of(csv);
  if (lines.empty()) throw InputError(source + ": empty jamming table");
  const auto head = split_fields(lines[0], ',');
  const auto column = [&](std::string_view name) {
    const auto it = std::find(head.begin(), head.end(), name);
    if (it == head.end())
      throw InputError(
          fmt::format("{}:1: no column {} (needs mu0, phi_max, phi_max_err)", source, name));
    return static_cast<std::size_t>(it - head.begin());
  };
  const std::size_t c_mu = column("mu0"), c_phi = column("phi_max"), c_err = column("phi_max_err");
  JammingTable t;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    if (is_blank(lines[k])) continue;
    const auto f = split_fields(lines[k], ',');
    const auto number = [&](std::size_t c, std::string_view name, bool empty_is_zero) {
      const std::string text = c < f.size() ? f[c] : std::string();
      if (text.empty() && empty_is_zero) return 0.0;
      const auto v = parse_number(text);
      if (!v || !std::isfinite(*v))
        throw InputError(
            fmt::format("{}:{}: {} = \"{}\" is not a finite number", source, k + 1, name, text));
      return *v;
    };
    JammingPoint p{number(c_mu, "mu0", false), number(c_phi, "phi_max", false),
                   number(c_err, "phi_max_err", true)};
    const double previous = t.points_.empty() ? -1.0 : t.points_.back().mu0;
    if (t.points_.empty() ? p.mu0 != 0.0 : p.mu0 <= previous)
      throw InputError(
          fmt::format("{}:{}: mu0 = {}: the table must start at mu0 = 0 (the frictionless "
                      "phi_max_HD) and increase strictly",
                      source, k + 1, p.mu0));
    if (!(p.phi_max > 0.0 && p.phi_max < 0.74) || p.phi_max_err < 0.0)
      throw InputError(
          fmt::format("{}:{}: phi_max = {} +- {}: must be in (0, 0.74) with a non-negative error",
                      source, k + 1, p.phi_max, p.phi_max_err));
    t.points_.push_back(p);
  }
  if (t.points_.empty()) throw InputError(source + ": the jamming table has no rows");
  return t;
}

JammingTable JammingTable::read(const std::filesystem::path& file) {
  std::string text;
  for (const auto& line : read_text_lines(file)) text += line + "\n";
  return parse(text, file.string());
}

JammingTable JammingTable::builtin() {
  return parse(kJammingTableCsv, "data/jamming/phi_max_bl.csv (built in)");
}

Estimate JammingTable::phi_max_bl(double mu0) const {
  const auto& p = points_;
  if (mu0 >= p.back().mu0) return {p.back().phi_max, p.back().phi_max_err};
  std::size_t k = 1;
  while (p[k].mu0 < mu0) ++k;
  const double w = (mu0 - p[k - 1].mu0) / (p[k].mu0 - p[k - 1].mu0);
  return {(1.0 - w) * p[k - 1].phi_max + w * p[k].phi_max,
          (1.0 - w) * p[k - 1].phi_max_err + w * p[k].phi_max_err};
}

std::string_view flow_regime_name(FlowRegime r) {
  switch (r) {
    case FlowRegime::Cst:
      return "cst";
    case FlowRegime::Dst:
      return "dst";
    case FlowRegime::NoFlow:
      break;
  }
  return "no_flow";
}

Prediction predict_regime(const JammingTable& table, double mu0, double phi) {
  Prediction out;
  out.phi_max_bl = table.phi_max_bl(mu0);
  out.phi_rcp = table.phi_rcp();
  out.regime = phi > out.phi_rcp.value      ? FlowRegime::NoFlow
               : phi > out.phi_max_bl.value ? FlowRegime::Dst
                                            : FlowRegime::Cst;
  const auto sigmas = [&](const Estimate& boundary) {
    const double d = std::abs(phi - boundary.value);
    return boundary.error > 0.0 ? d / boundary.error : std::numeric_limits<double>::infinity();
  };
  // Where the two boundaries coincide (high friction is never above mu0 = 0,
  // but a table may meet it), the nearer one decides.
  out.margin_sigma = std::min(sigmas(out.phi_max_bl), sigmas(out.phi_rcp));
  out.uncertain = out.margin_sigma < 2.0;
  return out;
}

}  // namespace dilatant::analysis
