#pragma once
// Student's t distribution, for confidence intervals of fits with few points
// (a thickening window often has 4-8 points, where the normal quantile 1.96
// would understate a 95% interval by up to a factor 2).
//
//   CDF(t; nu) = 1 - I_{nu/(nu+t^2)}(nu/2, 1/2) / 2   for t >= 0,
// with I_x(a, b) the regularised incomplete beta function, evaluated by its
// continued fraction (DLMF 8.17.22) with the modified Lentz method.

namespace dilatant::analysis {

// I_x(a, b) for a, b > 0 and x in [0, 1].
double regularized_incomplete_beta(double a, double b, double x);

double student_t_cdf(double t, double dof);

// The t with CDF(t; dof) = p, for p in (0, 1) and dof > 0.
double student_t_quantile(double p, double dof);

}  // namespace dilatant::analysis
