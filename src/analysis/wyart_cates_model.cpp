#include "analysis/wyart_cates_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dilatant::analysis {
namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr double kDiverges = std::numeric_limits<double>::infinity();

// The scans below run over t = ln x, x = (sigma*/sigma)^beta: from x = e^-18
// (sigma far above sigma*, f = 1 to 1e-8) to x = 50 (f = e^-50: frictionless).
constexpr double kLowT = -18.0;
constexpr double kHighT = 3.912;  // ln 50
constexpr int kScanNodes = 2400;
constexpr int kBisections = 80;

double friction_span(const WyartCatesParameters& p) { return p.phi_0 - p.phi_m; }

// Eq. (*) of the header at x: d ln eta / d ln sigma.
double slope_at_x(const WyartCatesParameters& p, double phi, double x) {
  const double e = std::exp(-x);
  const double phi_j = p.phi_0 - friction_span(p) * e;
  if (!(phi < phi_j)) return kDiverges;
  return p.alpha * p.beta * phi * friction_span(p) * x * e / (phi_j * (phi_j - phi));
}

// The smallest t at which the suspension flows: ln x_SJ for phi >= phi_m (x
// beyond which phi_J > phi), else the scan's lower end.
double lowest_flowing_t(const WyartCatesParameters& p, double phi) {
  if (phi < p.phi_m) return kLowT;
  const double x_sj = std::log(friction_span(p) / (p.phi_0 - phi));
  return std::log(x_sj);
}

double sigma_at_t(const WyartCatesParameters& p, double t) {
  return p.sigma_star * std::exp(-t / p.beta);  // sigma = sigma* x^(-1/beta)
}

// Grid nodes over the flowing part of t; the first node sits just inside it.
std::vector<double> scan_nodes(const WyartCatesParameters& p, double phi) {
  const double lo = std::max(kLowT, lowest_flowing_t(p, phi)) + 1e-9;
  std::vector<double> t(kScanNodes);
  for (int k = 0; k < kScanNodes; ++k)
    t[static_cast<std::size_t>(k)] = lo + (kHighT - lo) * k / (kScanNodes - 1);
  return t;
}

// Where slope(t) - 1 changes sign between a and b (bisection; the sign at a
// is kept).
double crossing(const WyartCatesParameters& p, double phi, double a, double b) {
  const bool above_at_a = slope_at_x(p, phi, std::exp(a)) > 1.0;
  for (int k = 0; k < kBisections; ++k) {
    const double m = 0.5 * (a + b);
    if ((slope_at_x(p, phi, std::exp(m)) > 1.0) == above_at_a)
      a = m;
    else
      b = m;
  }
  return 0.5 * (a + b);
}

struct SlopePeak {
  double t = kNoValue;
  double slope = -kDiverges;
};

// The largest slope over the flowing stresses at phi < phi_m: a scan, then a
// golden-section search between the best node's neighbours.
SlopePeak peak_slope(const WyartCatesParameters& p, double phi) {
  const std::vector<double> t = scan_nodes(p, phi);
  std::size_t best = 0;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (slope_at_x(p, phi, std::exp(t[k])) > slope_at_x(p, phi, std::exp(t[best]))) best = k;
  double a = t[best == 0 ? 0 : best - 1], b = t[std::min(best + 1, t.size() - 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < kBisections; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (slope_at_x(p, phi, std::exp(c)) > slope_at_x(p, phi, std::exp(d)))
      b = d;
    else
      a = c;
  }
  const double tm = 0.5 * (a + b);
  return {tm, slope_at_x(p, phi, std::exp(tm))};
}

}  // namespace

double frictional_fraction(const WyartCatesParameters& p, double sigma) {
  return std::exp(-std::pow(p.sigma_star / sigma, p.beta));
}

double jamming_fraction(const WyartCatesParameters& p, double sigma) {
  const double f = frictional_fraction(p, sigma);
  return f * p.phi_m + (1.0 - f) * p.phi_0;
}

double wyart_cates_viscosity(const WyartCatesParameters& p, double phi, double sigma) {
  const double phi_j = jamming_fraction(p, sigma);
  if (!(phi < phi_j)) return kDiverges;
  return p.A * std::pow(1.0 - phi / phi_j, -p.alpha);
}

double thickening_slope(const WyartCatesParameters& p, double phi, double sigma) {
  return slope_at_x(p, phi, std::pow(p.sigma_star / sigma, p.beta));
}

double shear_jamming_stress(const WyartCatesParameters& p, double phi) {
  if (!(p.phi_m < p.phi_0) || phi < p.phi_m) return kDiverges;
  if (phi >= p.phi_0) return 0.0;
  // phi_J(sigma) = phi  <=>  e^(-x) = (phi_0 - phi)/Delta.
  return p.sigma_star * std::pow(std::log(friction_span(p) / (p.phi_0 - phi)), -1.0 / p.beta);
}

TurningRange turning_range(const WyartCatesParameters& p, double phi) {
  TurningRange none{kNoValue, kNoValue};
  if (!(p.phi_m < p.phi_0) || phi >= p.phi_0) return none;
  const std::vector<double> t = scan_nodes(p, phi);
  const auto above = [&](double tk) { return slope_at_x(p, phi, std::exp(tk)) > 1.0; };
  // The outermost crossings: the S spans everything between them.
  std::size_t first = t.size(), last = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!above(t[k])) continue;
    first = std::min(first, k);
    last = k;
  }
  if (first == t.size()) return none;
  // Small t is high stress: the high end is at `first`, the low end at `last`.
  TurningRange r;
  r.high = phi >= p.phi_m ? shear_jamming_stress(p, phi)
           : first == 0   ? sigma_at_t(p, t[0])
                          : sigma_at_t(p, crossing(p, phi, t[first], t[first - 1]));
  r.low = last + 1 == t.size() ? sigma_at_t(p, t.back())
                               : sigma_at_t(p, crossing(p, phi, t[last], t[last + 1]));
  return r;
}

DstOnset dst_onset(const WyartCatesParameters& p) {
  if (!(p.phi_m < p.phi_0)) return {kNoValue, kNoValue};
  // The peak slope grows with phi at every x (Eq. (*): phi/(phi_J (phi_J - phi))
  // does), so the lowest phi where it reaches 1 is found by bisection.
  double lo = 0.0, hi = p.phi_m * (1.0 - 1e-12);
  if (peak_slope(p, hi).slope <= 1.0) return {p.phi_m, kDiverges};
  for (int k = 0; k < kBisections; ++k) {
    const double m = 0.5 * (lo + hi);
    (peak_slope(p, m).slope > 1.0 ? hi : lo) = m;
  }
  const double phi = 0.5 * (lo + hi);
  return {phi, sigma_at_t(p, peak_slope(p, phi).t)};
}

FlowState flow_state(const WyartCatesParameters& p, double phi, double sigma) {
  if (!(phi < jamming_fraction(p, sigma))) return FlowState::Jammed;
  return thickening_slope(p, phi, sigma) > 1.0 ? FlowState::TurnsBack : FlowState::Flows;
}

std::string flow_state_name(FlowState s) {
  switch (s) {
    case FlowState::Flows:
      return "flows";
    case FlowState::TurnsBack:
      return "turns_back";
    case FlowState::Jammed:
      return "jammed";
  }
  return "";
}

std::string flow_curve_regime(const WyartCatesParameters& p, double phi) {
  if (!(p.phi_m < p.phi_0)) return phi < p.phi_0 ? "cst" : "no_flow";
  if (phi >= p.phi_0) return "no_flow";
  if (phi >= p.phi_m) return "shear_jamming";
  return phi < dst_onset(p).phi ? "cst" : "dst";
}

}  // namespace dilatant::analysis
