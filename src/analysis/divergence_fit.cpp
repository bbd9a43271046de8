#include "analysis/divergence_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/levenberg_marquardt.hpp"
#include "analysis/polynomial_fit.hpp"

namespace dilatant::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The phi_max grid of the starting point: from the largest phi + 1e-4 to + 0.3.
constexpr double kGridLow = 1e-4;
constexpr double kGridHigh = 0.3;
constexpr int kGridNodes = 120;

double largest_phi(const PhiSeries& s) {
  double m = 0.0;
  for (const auto& p : s.points) m = std::max(m, p.phi);
  return m;
}

// Parameters: theta = (ln A, alpha, phi_max of each series that is fitted).
class Problem {
 public:
  explicit Problem(const std::vector<PhiSeries>& series) : series_(series) {
    for (std::size_t s = 0; s < series.size(); ++s) {
      slot_.push_back(series[s].phi_max ? -1 : static_cast<int>(2 + free_++));
      points_ += series[s].points.size();
    }
  }

  std::size_t parameters() const { return 2 + free_; }
  std::size_t points() const { return points_; }

  double phi_max(const Eigen::VectorXd& theta, std::size_t s) const {
    return slot_[s] < 0 ? *series_[s].phi_max : theta[slot_[s]];
  }

  bool feasible(const Eigen::VectorXd& theta) const {
    for (std::size_t s = 0; s < series_.size(); ++s) {
      const double pm = phi_max(theta, s);
      if (!(pm > largest_phi(series_[s]) && pm < 1.0)) return false;
    }
    return std::isfinite(theta[0]) && std::isfinite(theta[1]);
  }

  // Weighted residuals r_i = (n_i - 1 - A x^-alpha) / sigma_i and, if asked, their
  // Jacobian: dm/dlnA = m, dm/dalpha = -m ln x, dm/dphi_max = -alpha m phi / (x phi_max^2).
  Eigen::VectorXd residuals(const Eigen::VectorXd& theta, Eigen::MatrixXd* jacobian) const {
    Eigen::VectorXd r(static_cast<Eigen::Index>(points_));
    if (jacobian) jacobian->setZero(r.size(), static_cast<Eigen::Index>(parameters()));
    const double A = std::exp(theta[0]), alpha = theta[1];
    Eigen::Index i = 0;
    for (std::size_t s = 0; s < series_.size(); ++s) {
      const double pm = phi_max(theta, s);
      for (const auto& p : series_[s].points) {
        const double x = (pm - p.phi) / pm;
        const double m = A * std::pow(x, -alpha);
        r[i] = (p.n - 1.0 - m) / p.n_sigma;
        if (jacobian) {
          (*jacobian)(i, 0) = -m / p.n_sigma;
          (*jacobian)(i, 1) = m * std::log(x) / p.n_sigma;
          if (slot_[s] >= 0)
            (*jacobian)(i, slot_[s]) = alpha * m * p.phi / (x * pm * pm) / p.n_sigma;
        }
        ++i;
      }
    }
    return r;
  }

  const std::vector<PhiSeries>& series() const { return series_; }
  int slot(std::size_t s) const { return slot_[s]; }

 private:
  const std::vector<PhiSeries>& series_;
  std::vector<int> slot_;  // index of the series' phi_max in theta, -1 when given
  std::size_t free_ = 0;
  std::size_t points_ = 0;
};

struct Node {
  double chi2 = std::numeric_limits<double>::infinity();
  double log_A = std::log(0.05);
  double alpha = 1.0;
  double phi_max = kNaN;
};

// Straight line ln(n-1) = ln A - alpha ln x through the points with n > 1 at one
// phi_max; its chi2 measured on n itself.
Node line_at(const PhiSeries& s, double pm) {
  std::vector<double> lx, ly, sig;
  for (const auto& p : s.points) {
    if (!(p.n > 1.0)) continue;
    lx.push_back(std::log((pm - p.phi) / pm));
    ly.push_back(std::log(p.n - 1.0));
    sig.push_back(p.n_sigma / (p.n - 1.0));
  }
  Node node;
  if (lx.size() < 2) return node;
  const PolynomialFit line = fit_polynomial(lx, ly, sig, 1);
  node.alpha = -line.coefficients[1];
  node.log_A = line.coefficients[0] - line.coefficients[1] * line.x0;
  node.phi_max = pm;
  node.chi2 = 0.0;
  for (const auto& p : s.points) {
    const double r =
        (p.n - 1.0 - divergence_model(p.phi, pm, std::exp(node.log_A), node.alpha)) / p.n_sigma;
    node.chi2 += r * r;
  }
  return node;
}

Node best_node(const PhiSeries& s) {
  if (s.phi_max) return line_at(s, *s.phi_max);
  Node best;
  const double top = largest_phi(s);
  for (int k = 0; k < kGridNodes; ++k) {
    const double delta =
        kGridLow * std::pow(kGridHigh / kGridLow, static_cast<double>(k) / (kGridNodes - 1));
    if (top + delta >= 1.0) break;
    const Node node = line_at(s, top + delta);
    if (node.chi2 < best.chi2) best = node;
  }
  return best;
}

Eigen::VectorXd starting_point(const Problem& problem) {
  Eigen::VectorXd theta(static_cast<Eigen::Index>(problem.parameters()));
  double log_A = 0.0, alpha = 0.0;
  int found = 0;
  std::vector<Node> nodes;
  for (const auto& s : problem.series()) {
    nodes.push_back(best_node(s));
    if (std::isfinite(nodes.back().chi2)) {
      log_A += nodes.back().log_A;
      alpha += nodes.back().alpha;
      ++found;
    }
  }
  const Node fallback;
  theta[0] = found ? log_A / found : fallback.log_A;
  theta[1] = found ? alpha / found : fallback.alpha;
  for (std::size_t s = 0; s < nodes.size(); ++s) {
    if (problem.slot(s) < 0) continue;
    const double top = largest_phi(problem.series()[s]);
    theta[problem.slot(s)] = std::isfinite(nodes[s].phi_max) ? nodes[s].phi_max : top + 0.01;
  }
  return theta;
}

}  // namespace

double divergence_model(double phi, double phi_max, double A, double alpha) {
  return 1.0 + A * std::pow((phi_max - phi) / phi_max, -alpha);
}

double DivergenceFit::chi2_per_dof() const {
  return points > parameters ? chi2 / static_cast<double>(points - parameters) : kNaN;
}

DivergenceOutcome fit_divergence(const std::vector<PhiSeries>& series) {
  DivergenceOutcome out;
  std::size_t fitted_phi_max = 0, points = 0;
  for (const auto& s : series) {
    const std::size_t need = s.phi_max ? 1 : 2;
    if (s.points.size() < need) {
      out.why_not =
          fmt::format("sample {} has {} CST curve{} (needs {}{})", s.sample, s.points.size(),
                      s.points.size() == 1 ? "" : "s", need, s.phi_max ? "" : " to fit phi_max");
      return out;
    }
    if (s.phi_max && largest_phi(s) >= *s.phi_max) {
      out.why_not = fmt::format("sample {}: a CST curve at phi {} >= phi_max {}", s.sample,
                                largest_phi(s), *s.phi_max);
      return out;
    }
    fitted_phi_max += s.phi_max ? 0 : 1;
    points += s.points.size();
  }
  if (points <= 2 + fitted_phi_max) {
    out.why_not = fmt::format("{} CST curve{} for {} parameters (A, alpha{}); needs at least {}",
                              points, points == 1 ? "" : "s", 2 + fitted_phi_max,
                              fitted_phi_max ? ", phi_max" : "", 3 + fitted_phi_max);
    return out;
  }

  const Problem problem(series);
  const LeastSquaresProblem least_squares{
      [&](const Eigen::VectorXd& t, Eigen::MatrixXd* j) { return problem.residuals(t, j); },
      [&](const Eigen::VectorXd& t) { return problem.feasible(t); }};
  const Eigen::VectorXd theta = levenberg_marquardt(least_squares, starting_point(problem));
  Eigen::MatrixXd J;
  const Eigen::VectorXd r = problem.residuals(theta, &J);

  DivergenceFit fit;
  fit.points = problem.points();
  fit.parameters = problem.parameters();
  fit.chi2 = r.squaredNorm();
  const double scale = std::max(1.0, fit.chi2_per_dof());
  const Eigen::MatrixXd cov = least_squares_covariance(J, scale);
  const auto se = [&](int k) { return std::sqrt(cov(k, k)); };
  fit.A = {std::exp(theta[0]), std::exp(theta[0]) * se(0)};
  fit.alpha = {theta[1], se(1)};
  double sum_sq = 0.0;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const int slot = problem.slot(s);
    const double pm = problem.phi_max(theta, s);
    fit.phi_max.push_back({pm, slot < 0 ? kNaN : se(slot)});
    for (const auto& p : series[s].points) {
      if (!(p.n > 1.0)) continue;
      const double d = std::log10(
          (p.n - 1.0) / (divergence_model(p.phi, pm, fit.A.value, fit.alpha.value) - 1.0));
      sum_sq += d * d;
      ++fit.log_points;
    }
  }
  fit.rms_log10_deviation =
      fit.log_points ? std::sqrt(sum_sq / static_cast<double>(fit.log_points)) : kNaN;
  out.fit = fit;
  return out;
}

}  // namespace dilatant::analysis
