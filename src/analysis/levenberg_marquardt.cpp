#include "analysis/levenberg_marquardt.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant::analysis {

Eigen::VectorXd levenberg_marquardt(const LeastSquaresProblem& problem, Eigen::VectorXd theta,
                                    int max_iterations) {
  double lambda = 1e-3;
  Eigen::MatrixXd J;
  Eigen::VectorXd r = problem.residuals(theta, &J);
  double cost = r.squaredNorm();
  for (int iter = 0; iter < max_iterations; ++iter) {
    const Eigen::MatrixXd H = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool accepted = false;
    double new_cost = cost;
    Eigen::VectorXd step;
    while (!accepted && lambda < 1e16) {
      Eigen::MatrixXd damped = H;
      for (Eigen::Index k = 0; k < H.rows(); ++k) damped(k, k) += lambda * std::max(H(k, k), 1e-12);
      step = damped.ldlt().solve(-g);
      const Eigen::VectorXd trial = theta + step;
      if (problem.feasible(trial)) {
        const Eigen::VectorXd trial_r = problem.residuals(trial, nullptr);
        new_cost = trial_r.squaredNorm();
        if (std::isfinite(new_cost) && new_cost <= cost) {
          theta = trial;
          accepted = true;
          lambda = std::max(lambda / 3.0, 1e-12);
          break;
        }
      }
      lambda *= 4.0;
    }
    if (!accepted) break;  // no downhill step left: at the minimum
    const bool small_gain = cost - new_cost <= 1e-14 * std::max(cost, 1e-300);
    const bool small_step = step.norm() <= 1e-12 * (1.0 + theta.norm());
    r = problem.residuals(theta, &J);
    cost = new_cost;
    if (small_gain || small_step) break;
  }
  return theta;
}

Eigen::MatrixXd least_squares_covariance(const Eigen::MatrixXd& jacobian, double scale) {
  return (jacobian.transpose() * jacobian).completeOrthogonalDecomposition().pseudoInverse() *
         scale;
}

}  // namespace dilatant::analysis
