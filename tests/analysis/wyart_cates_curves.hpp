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

// One point at `phi` and `sigma`: the model's viscosity with log-normal noise
// of relative size `noise` (`normal` a unit normal of the caller's generator,
// kept across points), or, beyond phi_J, jammed (rate 0, no viscosity), as the
// sweep table gives it.
inline analysis::FlowPoint model_point(const analysis::WyartCatesParameters& p, double phi,
                                       double sigma, double noise, std::mt19937_64& rng,
                                       std::normal_distribution<double>& normal) {
  analysis::FlowPoint pt;
  pt.shear_stress = sigma;
  const double eta = analysis::wyart_cates_viscosity(p, phi, sigma);
  if (std::isfinite(eta)) {
    pt.viscosity = eta * std::exp(noise * normal(rng));
    pt.shear_rate = pt.shear_stress / pt.viscosity;
  } else {
    pt.jammed = true;
    pt.viscosity = std::nan("");
  }
  return pt;
}

// A stress ramp from 0.01 to 100 sigma*, 6 points a decade (model_point).
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
    for (int k = 0; k <= n; ++k)
      c.points.push_back(
          model_point(p, phi, p.sigma_star * low * std::pow(high / low, k / static_cast<double>(n)),
                      noise, rng, normal));
    out.push_back(c);
  }
  return out;
}

}  // namespace dilatant::test
