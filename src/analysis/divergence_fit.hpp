#pragma once
// The divergence of the Ostwald-de Waele exponent at the jamming fraction
// (Fernandez et al. 2013, Fig. 3d):
//
//     n - 1 = A x^(-alpha),    x = (phi_max - phi) / phi_max,
//
// fitted by weighted nonlinear least squares (Levenberg-Marquardt,
// levenberg_marquardt.hpp) of n itself, with weights 1/sigma_n^2 from the
// per-curve fits. A and alpha are common to all the series given; each series
// (a sample, i.e. a coating or a mu0) has its own phi_max, either given (a
// measured value, held fixed) or fitted. One series is the per-sample fit; all
// series together are the master-curve collapse.
//
// Uncertainties come from the covariance (J^T W J)^-1 at the optimum, scaled by
// chi2/dof when the scatter exceeds the error bars (never scaled down). A is
// fitted as ln A (it stays positive), so A_err = A * se(ln A).
//
// Starting point: for each series a grid over phi_max (from just above its
// largest phi to +0.3) with a straight-line fit of ln(n-1) on ln x at each
// node, the best node in chi2 of n; the common (ln A, alpha) start at the
// mean of the series' best nodes. phi_max is kept above the series' largest
// phi (x > 0) by rejecting steps that leave that region.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace dilatant::analysis {

struct PhiPoint {
  double phi = 0.0;
  double n = 0.0;
  double n_sigma = 0.0;  // standard error of n, > 0
};

struct PhiSeries {
  std::string sample;
  std::vector<PhiPoint> points;
  std::optional<double> phi_max;  // given: held fixed; else fitted
};

struct Estimate {
  double value = 0.0;
  double err = 0.0;  // one standard error; NaN when not available (a given value, dof 0)
};

struct DivergenceFit {
  Estimate A;
  Estimate alpha;
  std::vector<Estimate> phi_max;  // per series, in input order
  double chi2 = 0.0;
  std::size_t points = 0;
  std::size_t parameters = 0;
  // rms of log10((n - 1) / (A x^-alpha)) over the points with n > 1: how far,
  // in decades, the points lie from the curve on the collapse plot.
  double rms_log10_deviation = 0.0;
  std::size_t log_points = 0;

  double chi2_per_dof() const;
};

struct DivergenceOutcome {
  std::optional<DivergenceFit> fit;
  std::string why_not;  // when there is no fit: what is missing, e.g. "needs at least 4 curves"
};

// Needs more points than parameters (2 + the number of fitted phi_max), at
// least 2 points in each series whose phi_max is fitted, at least 1 in each
// other, and every phi below its given phi_max.
DivergenceOutcome fit_divergence(const std::vector<PhiSeries>& series);

// The model, for plots and tests.
double divergence_model(double phi, double phi_max, double A, double alpha);

}  // namespace dilatant::analysis
