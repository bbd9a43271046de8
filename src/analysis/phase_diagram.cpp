#include "analysis/phase_diagram.hpp"

#include <fmt/format.h>

#include <cmath>

namespace dilatant::analysis {

namespace {

// Nodes start + k step for k = 0..n, with a tolerance of 1e-9 steps so that
// an end written in decimal (0.66) is included.
std::size_t last_node(double start, double end, double step) {
  return static_cast<std::size_t>(std::floor((end - start) / step + 1e-9));
}

}  // namespace

std::string phase_diagram_csv(const JammingTable& table, const BulkFlowTable* bulk,
                              const PhaseGrid& grid) {
  std::string out = "mu0,phi,regime,phi_max_bl,phi_rcp,margin_sigma,uncertain,source\n";
  const std::size_t n_mu = last_node(0.0, grid.mu0_max, grid.mu0_step);
  const std::size_t n_phi = last_node(grid.phi_min, grid.phi_max, grid.phi_step);
  for (std::size_t i = 0; i <= n_mu; ++i) {
    const double mu0 = static_cast<double>(i) * grid.mu0_step;
    for (std::size_t j = 0; j <= n_phi; ++j) {
      const double phi = grid.phi_min + static_cast<double>(j) * grid.phi_step;
      const Prediction p = predict_regime(table, mu0, phi);
      const auto b = bulk ? decide_from_bulk(*bulk, mu0, phi) : BulkDecision{};
      const std::string margin = b.regime ? std::string()
                                 : std::isfinite(p.margin_sigma)
                                     ? fmt::format("{:.3g}", p.margin_sigma)
                                     : std::string("inf");
      out += fmt::format("{:.4g},{:.4g},{},{:.5f},{:.5f},{},{},{}\n", mu0, phi,
                         flow_regime_name(b.regime ? *b.regime : p.regime), p.phi_max_bl.value,
                         p.phi_rcp.value, margin, !b.regime && p.uncertain ? "true" : "false",
                         b.regime ? "bulk" : "sediment");
    }
  }
  return out;
}

}  // namespace dilatant::analysis
