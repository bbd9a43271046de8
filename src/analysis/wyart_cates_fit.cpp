#include "analysis/wyart_cates_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/levenberg_marquardt.hpp"

namespace dilatant::analysis {
namespace {

constexpr double kNotFitted = std::numeric_limits<double>::quiet_NaN();
// The starting grid: sigma* over the measured stresses, phi_0 from the
// largest phi + 1e-3 to + 0.25 (log-spaced: the viscosity is most sensitive
// close to it), phi_m from 0.1 below the smallest phi up to phi_0.
constexpr int kSigmaNodes = 20, kPhi0Nodes = 20, kPhiMNodes = 24;
constexpr double kPhi0Low = 1e-3, kPhi0High = 0.25, kPhiMBelow = 0.1;
// Exponents beyond this are not a suspension's (alpha 2, beta 1-2 in the
// references); the bound keeps a poorly constrained fit from running away.
constexpr double kMaxExponent = 20.0;

struct LogViscosityPoint {
  double phi = 0.0;
  double sigma = 0.0;
  double ln_eta = 0.0;
  double s = 1.0;  // standard error of ln eta
};

// Parameters theta = (phi_0, phi_m, ln sigma*, ln A[, alpha][, beta]).
class WyartCatesProblem {
 public:
  WyartCatesProblem(std::vector<LogViscosityPoint> data, const WyartCatesSettings& settings)
      : data_(std::move(data)), settings_(settings) {
    alpha_slot_ = settings.fit_alpha ? 4 : -1;
    beta_slot_ = settings.fit_beta ? (settings.fit_alpha ? 5 : 4) : -1;
  }

  std::size_t parameters() const {
    return 4 + (alpha_slot_ >= 0 ? 1 : 0) + (beta_slot_ >= 0 ? 1 : 0);
  }
  const std::vector<LogViscosityPoint>& data() const { return data_; }
  int alpha_slot() const { return alpha_slot_; }
  int beta_slot() const { return beta_slot_; }

  WyartCatesParameters model(const Eigen::VectorXd& theta) const {
    return {theta[0],
            theta[1],
            std::exp(theta[2]),
            std::exp(theta[3]),
            alpha_slot_ >= 0 ? theta[alpha_slot_] : settings_.alpha,
            beta_slot_ >= 0 ? theta[beta_slot_] : settings_.beta};
  }

  bool feasible(const Eigen::VectorXd& theta) const {
    if (!theta.allFinite()) return false;
    const WyartCatesParameters p = model(theta);
    if (!(p.phi_0 > 0.0 && p.phi_0 < 1.0 && p.phi_m > 0.0 && p.phi_m < 1.0)) return false;
    if (!(p.alpha > 0.0 && p.alpha < kMaxExponent && p.beta > 0.0 && p.beta < kMaxExponent))
      return false;
    for (const LogViscosityPoint& d : data_)
      if (!(d.phi < jamming_fraction(p, d.sigma))) return false;
    return true;
  }

  // ln eta_WC = ln A - alpha ln u, u = 1 - phi/phi_J, phi_J = phi_0 - Delta f,
  // f = e^-x, x = (sigma*/sigma)^beta, Delta = phi_0 - phi_m. Derivatives:
  //   d/dphi_J = -alpha phi / (phi_J^2 u)
  //   dphi_J/dphi_0 = 1 - f,  dphi_J/dphi_m = f,
  //   dphi_J/dln sigma* = Delta beta x f,  dphi_J/dbeta = Delta x f ln(sigma*/sigma),
  //   d/dln A = 1,  d/dalpha = -ln u.
  Eigen::VectorXd residuals(const Eigen::VectorXd& theta, Eigen::MatrixXd* jacobian) const {
    const WyartCatesParameters p = model(theta);
    const auto n = static_cast<Eigen::Index>(data_.size());
    Eigen::VectorXd r(n);
    if (jacobian) jacobian->setZero(n, static_cast<Eigen::Index>(parameters()));
    const double delta = p.phi_0 - p.phi_m;
    for (Eigen::Index i = 0; i < n; ++i) {
      const LogViscosityPoint& d = data_[static_cast<std::size_t>(i)];
      const double log_ratio = std::log(p.sigma_star / d.sigma);
      const double x = std::exp(p.beta * log_ratio);
      const double f = std::exp(-x);
      const double phi_j = p.phi_0 - delta * f;
      const double u = 1.0 - d.phi / phi_j;
      const double ln_u = std::log(u);
      r[i] = (d.ln_eta - (std::log(p.A) - p.alpha * ln_u)) / d.s;
      if (!jacobian) continue;
      const double dm_dphi_j = -p.alpha * d.phi / (phi_j * phi_j * u);
      auto& J = *jacobian;
      // dr = -dm / s
      J(i, 0) = -dm_dphi_j * (1.0 - f) / d.s;
      J(i, 1) = -dm_dphi_j * f / d.s;
      J(i, 2) = -dm_dphi_j * delta * p.beta * x * f / d.s;
      J(i, 3) = -1.0 / d.s;
      if (alpha_slot_ >= 0) J(i, alpha_slot_) = ln_u / d.s;
      if (beta_slot_ >= 0) J(i, beta_slot_) = -dm_dphi_j * delta * x * f * log_ratio / d.s;
    }
    return r;
  }

 private:
  std::vector<LogViscosityPoint> data_;
  WyartCatesSettings settings_;
  int alpha_slot_ = -1;
  int beta_slot_ = -1;
};

// A fitted point, for a refusal's message: where it is in its source.
struct PointPlace {
  const FlowCurve* curve = nullptr;
  const FlowPoint* point = nullptr;
  explicit operator bool() const { return point != nullptr; }
  std::string where() const { return fmt::format("line {} of {}", point->line, curve->source); }
};

// The first fitted point without a measured fraction, if any.
PointPlace fitted_point_without_bulk(const std::vector<FlowCurve>& curves) {
  for (const FlowCurve& c : curves)
    for (const FlowPoint& p : c.points)
      if (wyart_cates_fits_point(p) && !std::isfinite(p.phi_measured)) return {&c, &p};
  return {};
}

// The points that enter the fit, with s_i (see the header). Under
// Weights::Errors, `unweighed` is the first point without an error (else empty).
std::vector<LogViscosityPoint> points_to_fit(const std::vector<FlowCurve>& curves,
                                             const WyartCatesSettings& settings, bool bulk,
                                             bool& weighted, PointPlace& unweighed) {
  using Weights = WyartCatesSettings::Weights;
  std::vector<LogViscosityPoint> data;
  weighted = settings.weights != Weights::Uniform;
  unweighed = {};
  for (const FlowCurve& c : curves) {
    for (const FlowPoint& p : c.points) {
      if (!wyart_cates_fits_point(p)) continue;
      // The relative error of eta: the rate's where the stress was imposed;
      // asked for, else the viscosity's own (an imposed rate has no error).
      double relative = p.shear_rate > 0.0 ? p.shear_rate_err / p.shear_rate : 0.0;
      if (settings.weights == Weights::Errors) {
        if (!(relative > 0.0)) relative = p.viscosity_err / p.viscosity;
        if (!(relative > 0.0) && !unweighed) unweighed = {&c, &p};
      }
      weighted = weighted && relative > 0.0;
      data.push_back({bulk ? p.phi_measured : c.phi, p.shear_stress, std::log(p.viscosity),
                      std::max(relative, settings.noise_floor)});
    }
  }
  if (!weighted)
    for (LogViscosityPoint& d : data) d.s = 1.0;
  return data;
}

// The best node of the starting grid; ln A at each node is the weighted mean
// of ln eta + alpha ln u, the value that minimises the cost there.
Eigen::VectorXd grid_start(const WyartCatesProblem& problem, const WyartCatesSettings& settings) {
  const auto& data = problem.data();
  double phi_lo = 1.0, phi_hi = 0.0, s_lo = INFINITY, s_hi = 0.0;
  for (const LogViscosityPoint& d : data) {
    phi_lo = std::min(phi_lo, d.phi);
    phi_hi = std::max(phi_hi, d.phi);
    s_lo = std::min(s_lo, d.sigma);
    s_hi = std::max(s_hi, d.sigma);
  }
  const double phi_m_low = std::max(phi_lo - kPhiMBelow, 0.05);
  double best_cost = INFINITY;
  Eigen::VectorXd best(static_cast<Eigen::Index>(problem.parameters()));
  std::vector<double> f(data.size());
  for (int a = 0; a < kSigmaNodes; ++a) {
    const double sigma_star = s_lo * std::pow(s_hi / s_lo, a / (kSigmaNodes - 1.0));
    for (std::size_t i = 0; i < data.size(); ++i)
      f[i] = std::exp(-std::pow(sigma_star / data[i].sigma, settings.beta));
    for (int b = 0; b < kPhi0Nodes; ++b) {
      const double phi_0 =
          phi_hi + kPhi0Low * std::pow(kPhi0High / kPhi0Low, b / (kPhi0Nodes - 1.0));
      if (phi_0 >= 1.0) break;
      for (int c = 0; c < kPhiMNodes; ++c) {
        const double phi_m = phi_m_low + (phi_0 - phi_m_low) * c / static_cast<double>(kPhiMNodes);
        double sw = 0.0, swy = 0.0, swyy = 0.0;
        bool ok = true;
        for (std::size_t i = 0; i < data.size() && ok; ++i) {
          const double phi_j = phi_0 - (phi_0 - phi_m) * f[i];
          ok = data[i].phi < phi_j;
          const double y = data[i].ln_eta + settings.alpha * std::log(1.0 - data[i].phi / phi_j);
          const double w = 1.0 / (data[i].s * data[i].s);
          sw += w;
          swy += w * y;
          swyy += w * y * y;
        }
        const double cost = swyy - swy * swy / sw;
        if (!ok || !(cost < best_cost)) continue;
        best_cost = cost;
        best.setZero();
        best[0] = phi_0;
        best[1] = phi_m;
        best[2] = std::log(sigma_star);
        best[3] = swy / sw;
      }
    }
  }
  if (problem.alpha_slot() >= 0) best[problem.alpha_slot()] = settings.alpha;
  if (problem.beta_slot() >= 0) best[problem.beta_slot()] = settings.beta;
  return best;
}

// A choice's name in its table (the first, the default, for a value not in it).
template <class Choice, std::size_t N>
const char* name_of(const std::array<ChoiceName<Choice>, N>& names, Choice value) {
  for (const ChoiceName<Choice>& c : names)
    if (c.value == value) return c.name;
  return names.front().name;
}

}  // namespace

bool wyart_cates_fits_point(const FlowPoint& p) {
  return p.valid && !p.jammed && p.viscosity > 0.0 && std::isfinite(p.viscosity) &&
         p.shear_stress > 0.0;
}

double WyartCatesFit::chi2_per_dof() const {
  return points > parameters ? chi2 / static_cast<double>(points - parameters) : kNotFitted;
}

WyartCatesParameters WyartCatesFit::model() const {
  return {phi_0.value, phi_m.value, sigma_star.value, A.value, alpha.value, beta.value};
}

const char* phi_basis_name(WyartCatesSettings::Phi phi) { return name_of(kPhiBasisNames, phi); }

const char* weights_name(WyartCatesSettings::Weights weights) {
  return name_of(kWeightsNames, weights);
}

bool every_fitted_point_has_bulk(const std::vector<FlowCurve>& curves) {
  return !fitted_point_without_bulk(curves);
}

double fitted_phi(const FlowCurve& curve, bool bulk) {
  if (!bulk) return curve.phi;
  for (const bool fitted_only : {true, false}) {
    double sum = 0.0;
    int n = 0;
    for (const FlowPoint& p : curve.points)
      if (std::isfinite(p.phi_measured) && (!fitted_only || wyart_cates_fits_point(p))) {
        sum += p.phi_measured;
        ++n;
      }
    if (n > 0) return sum / n;
  }
  return curve.phi;
}

WyartCatesOutcome fit_wyart_cates(const std::vector<FlowCurve>& curves,
                                  const WyartCatesSettings& settings) {
  WyartCatesOutcome out;
  const PointPlace without = fitted_point_without_bulk(curves);
  if (settings.phi == WyartCatesSettings::Phi::Bulk && without) {
    out.why_not = fmt::format(
        "the fit in the bulk fraction needs every fitted point's phi_bulk; the point of {} has "
        "none (a rheometer file has none: fit it in its nominal phi)",
        without.where());
    return out;
  }
  const bool bulk = settings.phi == WyartCatesSettings::Phi::Bulk ||
                    (settings.phi == WyartCatesSettings::Phi::Auto && !without);
  bool weighted = false;
  PointPlace unweighed;
  std::vector<LogViscosityPoint> data = points_to_fit(curves, settings, bulk, weighted, unweighed);
  if (unweighed) {
    out.why_not = fmt::format(
        "the fit weighted by errors needs every fitted point's gamma_dot_err or eta_err; the "
        "point of {} has neither",
        unweighed.where());
    return out;
  }
  // Curves at distinct nominal phi: with the measured fraction every point
  // has its own, but the growth with phi is still told by the curves.
  std::vector<double> nominal, phis;
  for (const FlowCurve& c : curves) {
    if (std::none_of(c.points.begin(), c.points.end(), wyart_cates_fits_point)) continue;
    if (std::find(nominal.begin(), nominal.end(), c.phi) == nominal.end()) nominal.push_back(c.phi);
    const double phi = fitted_phi(c, bulk);
    if (std::find(phis.begin(), phis.end(), phi) == phis.end()) phis.push_back(phi);
  }
  std::sort(phis.begin(), phis.end());
  if (nominal.size() < 2) {
    out.why_not = fmt::format(
        "flowing points at {} volume fraction{}; the fit needs flow curves at 2 or more phi "
        "(phi_0 and A are told apart only by how the viscosity grows with phi)",
        nominal.size(), nominal.size() == 1 ? "" : "s");
    return out;
  }
  const WyartCatesProblem problem(std::move(data), settings);
  const std::size_t points = problem.data().size();
  if (points <= problem.parameters()) {
    out.why_not = fmt::format("{} flowing points for {} parameters; needs at least {}", points,
                              problem.parameters(), problem.parameters() + 1);
    return out;
  }
  const LeastSquaresProblem least_squares{
      [&](const Eigen::VectorXd& t, Eigen::MatrixXd* j) { return problem.residuals(t, j); },
      [&](const Eigen::VectorXd& t) { return problem.feasible(t); }};
  const Eigen::VectorXd start = grid_start(problem, settings);
  if (!problem.feasible(start)) {
    out.why_not = "no starting point of the grid keeps every point below phi_J";
    return out;
  }
  const Eigen::VectorXd theta = levenberg_marquardt(least_squares, start);
  Eigen::MatrixXd J;
  const Eigen::VectorXd r = problem.residuals(theta, &J);

  WyartCatesFit fit;
  fit.points = points;
  fit.parameters = problem.parameters();
  fit.curves = nominal.size();
  fit.phi_bulk = bulk;
  fit.phi = phis;
  fit.weighted = weighted;
  fit.chi2 = r.squaredNorm();
  fit.stress_low = INFINITY;
  for (const LogViscosityPoint& d : problem.data()) {
    fit.stress_low = std::min(fit.stress_low, d.sigma);
    fit.stress_high = std::max(fit.stress_high, d.sigma);
  }
  // Unweighted: the scatter is measured from the residuals (scale = chi2/dof).
  const double scale = weighted ? std::max(1.0, fit.chi2_per_dof()) : fit.chi2_per_dof();
  const Eigen::MatrixXd cov = least_squares_covariance(J, scale);
  const auto se = [&](int k) { return k < 0 ? kNotFitted : std::sqrt(cov(k, k)); };
  fit.names = {"phi_0", "phi_m", "ln_sigma_star", "ln_A"};
  if (settings.fit_alpha) fit.names.emplace_back("alpha");
  if (settings.fit_beta) fit.names.emplace_back("beta");
  fit.covariance = cov;
  const WyartCatesParameters p = problem.model(theta);
  fit.phi_0 = {p.phi_0, se(0)};
  fit.phi_m = {p.phi_m, se(1)};
  fit.sigma_star = {p.sigma_star, p.sigma_star * se(2)};
  fit.A = {p.A, p.A * se(3)};
  fit.alpha = {p.alpha, se(problem.alpha_slot())};
  fit.beta = {p.beta, se(problem.beta_slot())};
  double sum_sq = 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double d = r[i] * problem.data()[static_cast<std::size_t>(i)].s / std::log(10.0);
    sum_sq += d * d;
  }
  fit.rms_log10_deviation = std::sqrt(sum_sq / static_cast<double>(points));

  if (!(p.sigma_star > fit.stress_low && p.sigma_star < fit.stress_high)) {
    out.why_not = fmt::format(
        "the fitted sigma* = {:.4g} lies outside the measured stresses {:.4g}..{:.4g}: the "
        "curves do not cross the onset of frictional contacts, so sigma* and phi_m are not "
        "determined (measure from well below to well above the thickening)",
        p.sigma_star, fit.stress_low, fit.stress_high);
    return out;
  }
  out.fit = fit;
  return out;
}

}  // namespace dilatant::analysis
