#pragma once
// The Wyart–Cates model (wyart_cates_model.hpp) fitted to the flow curves of
// one sample at several phi: phi_0, phi_m, sigma* and A, and optionally the
// exponents alpha and beta (fixed at 2 and 1 by default, the values of Wyart &
// Cates, PRL 112, 098302, 2014, and Singh, Mari, Denn & Morris, J. Rheol. 62,
// 457, 2018).
//
// What is fitted: ln eta of every valid, flowing point (a jammed point has no
// viscosity; a point outside the simulation model's validity is drawn, never
// fitted), by weighted nonlinear least squares (levenberg_marquardt.hpp):
//
//     r_i = (ln eta_i - ln eta_WC(sigma_i, phi_i)) / s_i.
//
// phi_i is the point's own measured fraction where the data have one (a
// sweep's phi_bulk: the bulk of a wall cell dilates 0.01-0.02 below its nominal
// phi, and with the stress; WyartCatesSettings::phi), else its curve's nominal
// phi. The model relates the viscosity to the fraction the suspension has, so
// a fit in nominal phi of a wall cell shifts phi_0 and phi_m by the dilation.
//
// In logarithms because the viscosity spans decades and its scatter is
// relative. s_i (WyartCatesSettings::weights) is by default the relative
// error of the shear rate (= that of eta under an imposed stress) when every
// point has one (a sweep's gamma_dot_err; at least noise_floor); asked for,
// the error of eta itself where the rate has none (eta_err under an imposed
// rate). The covariance is then scaled by chi2/dof when the scatter exceeds
// the error bars (never down). Rheometer exports carry no errors:
// s_i = 1, and the covariance is scaled by chi2/dof, i.e. the scatter of ln eta is measured from
// the residuals. Parameters: phi_0, phi_m, ln sigma*, ln A (positive), alpha, beta; sigma*_err =
// sigma* se(ln sigma*), likewise A.
//
// Start: a grid over (sigma* across the measured stresses, phi_0 above the
// largest phi, phi_m), with ln A the weighted mean it must be at each node;
// the best node starts the descent. A step that puts a measured point at or
// beyond phi_J (an infinite model viscosity) is refused.
//
// Not fitted (why_not): fewer than 2 nominal phi (phi_0 and A are told apart
// only by how the viscosity grows with phi), no more points than parameters, a
// fitted sigma* outside the measured stresses (the curves do not cross the
// onset of frictional contacts, so sigma* and phi_m are not determined), a
// point without phi_bulk under Phi::Bulk, or without an error under
// Weights::Errors (each named by its line and file).
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis/divergence_fit.hpp"
#include "analysis/flow_curve.hpp"
#include "analysis/wyart_cates_model.hpp"

namespace dilatant::analysis {

struct WyartCatesSettings {
  double alpha = 2.0;  // the held value, or the start of the fit
  double beta = 1.0;
  bool fit_alpha = false;
  bool fit_beta = false;
  // Relative error below which no point is trusted (as AnalysisSettings::noise_floor).
  double noise_floor = 0.005;
  // The volume fraction fitted: each point's measured one (Bulk: a sweep's
  // phi_bulk), its curve's nominal phi (Nominal), or Bulk when every fitted
  // point has one and Nominal otherwise (Auto: rheometer data have none).
  enum class Phi { Auto, Nominal, Bulk };
  Phi phi = Phi::Auto;
  // The residuals' weights: Auto, the rate errors when every fitted point has
  // one (a stress-controlled sweep), else uniform; Uniform, every point alike
  // (the scatter measured from the residuals); Errors, each point's error of
  // eta, the rate's or else the viscosity's own (eta_err of an imposed rate),
  // which every fitted point must have. Where the model's misfit exceeds the
  // points' statistical errors (docs/laws.md: chi2/dof 346-17306), the
  // errors weigh the most precise points as if the model were exact there.
  enum class Weights { Auto, Uniform, Errors };
  Weights weights = Weights::Auto;
};

// The names of the settings' choices, one table per choice: what the CLI's
// --wc-phi and --wc-weights and Python's phi= and weights= accept (case aside),
// and what wyart_cates.json's `settings` says.
template <class Choice>
struct ChoiceName {
  const char* name;
  Choice value;
};
inline constexpr std::array<ChoiceName<WyartCatesSettings::Phi>, 3> kPhiBasisNames{{
    {"auto", WyartCatesSettings::Phi::Auto},
    {"nominal", WyartCatesSettings::Phi::Nominal},
    {"bulk", WyartCatesSettings::Phi::Bulk},
}};
inline constexpr std::array<ChoiceName<WyartCatesSettings::Weights>, 3> kWeightsNames{{
    {"auto", WyartCatesSettings::Weights::Auto},
    {"uniform", WyartCatesSettings::Weights::Uniform},
    {"errors", WyartCatesSettings::Weights::Errors},
}};

// A choice's name in the tables above.
const char* weights_name(WyartCatesSettings::Weights weights);
const char* phi_basis_name(WyartCatesSettings::Phi phi);

struct WyartCatesFit {
  Estimate phi_0, phi_m, sigma_star, A, alpha, beta;  // err NaN when held fixed
  double chi2 = 0.0;
  std::size_t points = 0;
  std::size_t parameters = 0;
  std::size_t curves = 0;   // nominal volume fractions with fitted points
  bool phi_bulk = false;    // fitted in the points' measured fractions (else nominal)
  std::vector<double> phi;  // the curves' fitted_phi, distinct, ascending
  double stress_low = 0.0;  // the fitted points' stress range
  double stress_high = 0.0;
  bool weighted = false;             // s_i from the points' errors; else 1
  double rms_log10_deviation = 0.0;  // of eta from the model, in decades
  // The covariance of the fitted parameters, in the order of `names` (of
  // phi_0, phi_m, ln_sigma_star, ln_A, alpha, beta: those fitted), as scaled
  // for the errors above; for the errors of what the fit implies (phi_DST).
  std::vector<std::string> names;
  Eigen::MatrixXd covariance;

  double chi2_per_dof() const;
  WyartCatesParameters model() const;
};

struct WyartCatesOutcome {
  std::optional<WyartCatesFit> fit;
  std::string why_not;
};

// Whether a point enters the fit: valid, flowing, with a positive viscosity.
bool wyart_cates_fits_point(const FlowPoint& p);

// A curve's volume fraction in the fit's terms: its nominal phi, or (bulk) the
// mean measured fraction of its fitted points, of all its points when none is
// fitted, its nominal phi when none has one. For tables and the overlay.
double fitted_phi(const FlowCurve& curve, bool bulk);

// Whether every fitted point (wyart_cates_fits_point) has a measured fraction:
// what WyartCatesSettings::Phi::Auto decides by.
bool every_fitted_point_has_bulk(const std::vector<FlowCurve>& curves);

// The curves of one sample (their `sample` names are not read).
WyartCatesOutcome fit_wyart_cates(const std::vector<FlowCurve>& curves,
                                  const WyartCatesSettings& settings);

}  // namespace dilatant::analysis
