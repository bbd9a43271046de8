// Student's t quantiles against printed tables (4 decimals, e.g. Abramowitz &
// Stegun Table 26.10), and the incomplete beta function against closed forms.
#include "analysis/student_t.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dilatant::analysis::student_t_test {
namespace {

struct Tabulated {
  double p, dof, t;
};

TEST(StudentT, QuantilesMatchPrintedTables) {
  // The tables give 4 decimals: agreement to 1e-4 is all they can show.
  for (const Tabulated& row :
       {Tabulated{0.975, 1, 12.7062}, Tabulated{0.975, 2, 4.3027}, Tabulated{0.975, 5, 2.5706},
        Tabulated{0.975, 10, 2.2281}, Tabulated{0.975, 30, 2.0423}, Tabulated{0.95, 4, 2.1318},
        Tabulated{0.995, 3, 5.8409}}) {
    EXPECT_NEAR(student_t_quantile(row.p, row.dof), row.t, 1e-4)
        << "p " << row.p << ", dof " << row.dof;
  }
}

TEST(StudentT, TendsToTheNormalQuantileAndIsSymmetric) {
  // t(dof) -> normal: at dof 1e6 the difference is O(1/dof).
  EXPECT_NEAR(student_t_quantile(0.975, 1e6), 1.959964, 1e-5);
  EXPECT_NEAR(student_t_quantile(0.025, 7), -student_t_quantile(0.975, 7), 1e-12);
  for (double t : {0.3, 1.0, 4.0})
    EXPECT_NEAR(student_t_cdf(-t, 3), 1 - student_t_cdf(t, 3), 1e-14);
  // dof 1 is the Cauchy distribution: CDF = 1/2 + atan(t)/pi.
  EXPECT_NEAR(student_t_cdf(2.0, 1), 0.5 + std::atan(2.0) / std::numbers::pi, 1e-13);
}

TEST(IncompleteBeta, MatchesClosedForms) {
  for (double x : {0.01, 0.3, 0.5, 0.8, 0.99}) {
    EXPECT_NEAR(regularized_incomplete_beta(1, 1, x), x, 1e-13);                       // uniform
    EXPECT_NEAR(regularized_incomplete_beta(3, 1, x), x * x * x, 1e-13);               // x^a
    EXPECT_NEAR(regularized_incomplete_beta(1, 4, x), 1 - std::pow(1 - x, 4), 1e-13);  // 1-(1-x)^b
    // I_x(1/2, 1/2) = (2/pi) asin(sqrt x)
    EXPECT_NEAR(regularized_incomplete_beta(0.5, 0.5, x),
                2 / std::numbers::pi * std::asin(std::sqrt(x)), 1e-12);
  }
}

}  // namespace
}  // namespace dilatant::analysis::student_t_test
