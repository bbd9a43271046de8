#include "analysis/student_t.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dilatant::analysis {
namespace {

// The continued fraction 1/(1+ d1/(1+ d2/(1+ ...))) of DLMF 8.17.22, with
//   d_{2m+1} = -(a+m)(a+b+m) x / ((a+2m)(a+2m+1)),
//   d_{2m}   = m(b-m) x / ((a+2m-1)(a+2m)),
// by the modified Lentz method. Converges fast for x < (a+1)/(a+b+2).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEps = 1e-15;
  // State after the first level 1/(1 + ...): value 1, D = 1, C = "infinite".
  double c = 1.0 / kTiny;
  double d = 1.0;
  double f = 1.0;
  for (int k = 1; k <= 10000; ++k) {
    const int m = k / 2;
    const double dm = m;
    const double num = (k % 2 == 1)
                           ? -(a + dm) * (a + b + dm) * x / ((a + 2 * dm) * (a + 2 * dm + 1))
                           : dm * (b - dm) * x / ((a + 2 * dm - 1) * (a + 2 * dm));
    d = 1.0 + num * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + num / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    f *= c * d;
    if (std::abs(c * d - 1.0) < kEps) return f;
  }
  throw std::runtime_error("incomplete beta: continued fraction did not converge");
}

}  // namespace

double regularized_incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  // I_x(a,b) = x^a (1-x)^b / (a B(a,b)) * CF; the symmetry I_x(a,b) = 1 - I_{1-x}(b,a)
  // keeps the fraction in its fast region.
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - regularized_incomplete_beta(b, a, 1.0 - x);
  const double log_front = a * std::log(x) + b * std::log1p(-x) + std::lgamma(a + b) -
                           std::lgamma(a) - std::lgamma(b) - std::log(a);
  return std::exp(log_front) * beta_continued_fraction(a, b, x);
}

double student_t_cdf(double t, double dof) {
  const double tail = 0.5 * regularized_incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
  return t >= 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0) || !(dof > 0.0))
    throw std::invalid_argument("student_t_quantile: needs p in (0, 1) and dof > 0");
  if (p < 0.5) return -student_t_quantile(1.0 - p, dof);
  // Bisection on [0, hi]: the CDF is monotonic; 200 halvings reach double precision.
  double lo = 0.0, hi = 1.0;
  while (student_t_cdf(hi, dof) < p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace dilatant::analysis
