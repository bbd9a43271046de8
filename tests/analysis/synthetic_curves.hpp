#pragma once
// Synthetic stress-ramp flow curves with known answers: the model of
// examples/analysis/make_example.py, in C++ so that tests can draw as many
// noisy replicates as they need.
//
//   ln gdot = ln(tau_c / eta_N) + F(u),  u = ln(tau / tau_c),
//   F(u) = u - (1 - b)/m ln(1 + e^(m u)),  b = 1/(n + 1),
// Newtonian (gdot = tau/eta_N) well below tau_c, eta ∝ gdot^n well above; m sets
// the width of the crossover; b <= 0 is DST (the rate stops growing). The ramp
// descends from 700 to 0.01 in steps of about 1/10 decade (49 points, stored
// ascending); the measured rate carries log-normal noise of relative size `noise`.
#include <cmath>
#include <random>

#include "analysis/flow_curve.hpp"

namespace dilatant::test {

struct CurveModel {
  double eta_newtonian = 0.3;
  double onset_scale = 2.0;             // tau_c
  double n = 2.0;                       // ignored when rate_exponent is set
  double rate_exponent = std::nan("");  // b directly (e.g. < 0 for DST)
  double sharpness = 2.0;               // m
  double noise = 0.0;
  unsigned seed = 1;
  double low_stress_thinning = 0.0;  // eta up by this factor x e^(-ln(tau/0.01)) at low stress

  double b() const { return std::isnan(rate_exponent) ? 1.0 / (n + 1.0) : rate_exponent; }

  double shear_rate(double tau) const {
    const double u = std::log(tau / onset_scale), m = sharpness;
    // ln(1 + e^(m u)) without overflow.
    const double softplus =
        m * u > 0 ? m * u + std::log1p(std::exp(-m * u)) : std::log1p(std::exp(m * u));
    const double f = u - (1.0 - b()) / m * softplus;
    return onset_scale / eta_newtonian * std::exp(f) /
           (1.0 + low_stress_thinning * std::exp(-std::log(tau / 0.01)));
  }

  // Where eta = factor x eta_N: (1 + e^(m u))^((1-b)/m) = factor.
  double onset_stress(double factor = 1.1) const {
    const double m = sharpness;
    return onset_scale * std::pow(std::pow(factor, m / (1.0 - b())) - 1.0, 1.0 / m);
  }

  analysis::FlowCurve curve(double phi = 0.5, const std::string& sample = "S") const {
    analysis::FlowCurve c;
    c.source = "synthetic.csv";
    c.sample = sample;
    c.phi = phi;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    constexpr int kPoints = 49;
    for (int k = 0; k < kPoints; ++k) {
      const double tau = 0.01 * std::pow(7e4, k / 48.0);  // 0.01 .. 700 Pa
      analysis::FlowPoint p;
      p.shear_stress = tau;
      p.shear_rate = shear_rate(tau) * std::exp(noise * normal(rng));
      p.viscosity = tau / p.shear_rate;
      p.line = static_cast<std::size_t>(k + 2);
      c.points.push_back(p);
    }
    return c;
  }
};

}  // namespace dilatant::test
