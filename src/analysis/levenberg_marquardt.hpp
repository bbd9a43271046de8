#pragma once
// Weighted nonlinear least squares by Levenberg-Marquardt with Marquardt's
// diagonal scaling (Press et al., Numerical Recipes, 3rd ed., Sec. 15.5.2),
// shared by the fits of the analysis (divergence_fit.hpp, wyart_cates_fit.hpp).
//
// The caller gives the weighted residuals r(theta) = (y - model)/sigma and
// their Jacobian, and a feasible region: a step that leaves it (a jamming
// fraction below a measured phi, say) is refused like one that raises the
// cost, and the damping grows until a step is accepted or none is left.
#include <Eigen/Dense>
#include <functional>

namespace dilatant::analysis {

struct LeastSquaresProblem {
  // Weighted residuals at theta; fills *jacobian (d r / d theta) when not null.
  std::function<Eigen::VectorXd(const Eigen::VectorXd& theta, Eigen::MatrixXd* jacobian)> residuals;
  std::function<bool(const Eigen::VectorXd& theta)> feasible;
};

// The minimum of |r|^2 from a feasible start. Stops when a step no longer
// lowers the cost by 1e-14 of itself, when the step is below 1e-12 of |theta|,
// when no downhill step is left, or after max_iterations.
Eigen::VectorXd levenberg_marquardt(const LeastSquaresProblem& problem, Eigen::VectorXd theta,
                                    int max_iterations = 500);

// The covariance of the parameters at the optimum, (J^T J)^-1 * scale (a
// pseudo-inverse: a direction the data do not constrain has no finite
// error instead of a crash).
Eigen::MatrixXd least_squares_covariance(const Eigen::MatrixXd& jacobian, double scale);

}  // namespace dilatant::analysis
