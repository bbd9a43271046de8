#include "analysis/polynomial_fit.hpp"

#include <numeric>
#include <stdexcept>

namespace dilatant::analysis {

double PolynomialFit::operator()(double x) const {
  double value = 0.0, power = 1.0;
  for (Eigen::Index k = 0; k < coefficients.size(); ++k) {
    value += coefficients[k] * power;
    power *= x - x0;
  }
  return value;
}

PolynomialFit fit_polynomial(std::span<const double> x, std::span<const double> y,
                             std::span<const double> sigma, int degree) {
  const std::size_t n = x.size();
  const auto terms = static_cast<std::size_t>(degree) + 1;
  if (degree < 0 || y.size() != n || sigma.size() != n || n < terms)
    throw std::invalid_argument("fit_polynomial: needs matching sizes and more points than terms");
  PolynomialFit fit;
  fit.points = n;
  fit.x0 = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
  // Rows scaled by 1/sigma: an ordinary least-squares problem A c = b.
  Eigen::MatrixXd a(n, terms);
  Eigen::VectorXd b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    double power = 1.0 / sigma[i];
    for (std::size_t k = 0; k < terms; ++k) {
      a(row, static_cast<Eigen::Index>(k)) = power;
      power *= x[i] - fit.x0;
    }
    b[row] = y[i] / sigma[i];
  }
  const auto qr = a.colPivHouseholderQr();
  fit.coefficients = qr.solve(b);
  const Eigen::MatrixXd normal = a.transpose() * a;
  fit.covariance = normal.inverse();
  fit.chi2 = (a * fit.coefficients - b).squaredNorm();
  return fit;
}

}  // namespace dilatant::analysis
