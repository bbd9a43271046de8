#pragma once
// Weighted linear least squares of a polynomial, the building block of the
// flow-curve fits: the power law is a straight line in log-log (degree 1), and
// its straightness is tested with a quadratic (degree 2).
//
// Minimises chi2 = sum_i ((y_i - sum_k c_k (x_i - x0)^k) / sigma_i)^2, x0 the
// mean of x (centring keeps the normal equations well conditioned). The
// covariance is (X^T W X)^-1 with W = diag(1/sigma^2): the uncertainty the
// given sigmas imply, not rescaled by the scatter (callers decide).
#include <Eigen/Dense>
#include <cstddef>
#include <span>

namespace dilatant::analysis {

struct PolynomialFit {
  double x0 = 0.0;               // the centre of x
  Eigen::VectorXd coefficients;  // c_0 .. c_degree, in powers of (x - x0)
  Eigen::MatrixXd covariance;    // of the coefficients
  double chi2 = 0.0;
  std::size_t points = 0;

  std::size_t dof() const { return points - static_cast<std::size_t>(coefficients.size()); }
  double operator()(double x) const;
};

// Needs x.size() == y.size() == sigma.size() > degree and sigma > 0.
PolynomialFit fit_polynomial(std::span<const double> x, std::span<const double> y,
                             std::span<const double> sigma, int degree);

}  // namespace dilatant::analysis
