#pragma once
// Synthetic flow curves drawn from the Wyart–Cates model (wyart_cates_model.hpp)
// with known parameters and log-normal noise of a seeded generator: what the
// fit's and the report's tests give the fit to recover.
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "analysis/flow_curve.hpp"
#include "analysis/wyart_cates_model.hpp"

namespace dilatant::test {

// A stress ramp from 0.01 to 100 sigma*, 6 points a decade; points beyond
// phi_J are jammed (rate 0, no viscosity), as the sweep table gives them.
inline std::vector<analysis::FlowCurve> curves(const analysis::WyartCatesParameters& p,
                                               const std::vector<double>& phis, double noise,
                                               unsigned seed, double low = 0.01,
                                               double high = 100.0,
                                               const std::string& sample = "S") {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<analysis::FlowCurve> out;
  const int n = static_cast<int>(std::lround(6.0 * std::log10(high / low)));
  for (const double phi : phis) {
    // Strings constructed, not assigned: GCC 12 at -O3 reports a false
    // -Wstringop-overflow on assigning a literal here (GCC bug 105329).
    analysis::FlowCurve c{
        std::string("synthetic"), std::string(), std::string(sample), phi, std::nullopt, {}, 0};
    for (int k = 0; k <= n; ++k) {
      analysis::FlowPoint pt;
      pt.shear_stress = p.sigma_star * low * std::pow(high / low, k / static_cast<double>(n));
      const double eta = analysis::wyart_cates_viscosity(p, phi, pt.shear_stress);
      if (std::isfinite(eta)) {
        pt.viscosity = eta * std::exp(noise * normal(rng));
        pt.shear_rate = pt.shear_stress / pt.viscosity;
      } else {
        pt.jammed = true;
        pt.viscosity = std::nan("");
      }
      c.points.push_back(pt);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace dilatant::test
