#include "analysis/jamming_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/delimited_text.hpp"
#include "dilatant/builtin_tables.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {

JammingTable JammingTable::parse(const NumericCsv& csv) {
  constexpr std::string_view needs = "mu0, phi_max, phi_max_err";
  const std::size_t c_mu = csv.column("mu0", needs), c_phi = csv.column("phi_max", needs),
                    c_err = csv.column("phi_max_err", needs);
  JammingTable t;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    JammingPoint p{csv.number(r, c_mu, "mu0"), csv.number(r, c_phi, "phi_max"),
                   csv.number_or(r, c_err, "phi_max_err", 0.0)};
    const double previous = t.points_.empty() ? -1.0 : t.points_.back().mu0;
    if (t.points_.empty() ? p.mu0 != 0.0 : p.mu0 <= previous)
      csv.fail(r, fmt::format("mu0 = {}: the table must start at mu0 = 0 (the frictionless "
                              "phi_max_HD) and increase strictly",
                              p.mu0));
    if (!(p.phi_max > 0.0 && p.phi_max < 0.74) || p.phi_max_err < 0.0)
      csv.fail(r, fmt::format("phi_max = {} +- {}: must be in (0, 0.74) with a non-negative error",
                              p.phi_max, p.phi_max_err));
    t.points_.push_back(p);
  }
  if (t.points_.empty()) throw InputError(csv.source() + ": the jamming table has no rows");
  return t;
}

JammingTable JammingTable::read(const std::filesystem::path& file) {
  return parse(NumericCsv(read_text_lines(file), file.string()));
}

JammingTable JammingTable::builtin() {
  return parse(NumericCsv::from_text(kJammingTableCsv, "data/jamming/phi_max_bl.csv (built in)"));
}

MeasuredFraction JammingTable::phi_max_bl(double mu0) const {
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
  const auto sigmas = [&](const MeasuredFraction& boundary) {
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
