#include "analysis/curve_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/contact_onset.hpp"
#include "analysis/polynomial_fit.hpp"
#include "analysis/student_t.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The flat bottom: within 3 sigma of the minimum. The smoothed minimum of a
// noisy plateau lies about 2 sigma low, so a narrower band would keep only the
// low points and bias eta_newtonian down; a wider one would take in the foot of
// the thickening branch and any low-stress thinning, biasing it up.
constexpr double kPlateauSigmas = 3.0;
// A quadratic term beyond 2 standard errors means the window is curved. Lower
// thresholds cut the bias from the crossover at the foot of the window but
// shorten it (docs/analysis.md: 2 gives the least error on synthetic curves).
constexpr double kCurvatureSigmas = 2.0;
// 1.4826 x median absolute deviation estimates sigma of a normal distribution.
constexpr double kMadToSigma = 1.4826;
constexpr std::size_t kMinFitPoints = 3;
// Each point's noise is a standard error of its own (a run's mean over its
// steady samples, or a rheometer's scatter): the normal quantile applies, which
// the t quantile at 1000 degrees of freedom gives within 0.1%.
constexpr double kNormalDof = 1000.0;
// Rule 6's rate_falls turns a whole curve's regime on one step, so its false
// calls are held far below an interval's 5%: at most 1 in 1000 curves whose
// rate never falls (a fall beyond 3.1-4 combined sigmas for 1-30 steps). It
// also leaves room for error bars a little too small (a run's samples are
// correlated); the steps it is meant for are tens of sigmas deep.
constexpr double kRateFallFalseCalls = 1e-3;

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

// Sigma of y from the scatter of each inner point about the straight line
// through its two neighbours: r = y_i - ((1-t) y_{i-1} + t y_{i+1}) has variance
// sigma^2 (1 + (1-t)^2 + t^2). Robust (median) against the curvature at the bend.
double scatter_about_neighbours(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> z;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    // Equal stresses occur only in rate-controlled ramps sorted by stress.
    if (!(x[i + 1] > x[i - 1])) continue;
    const double t = (x[i] - x[i - 1]) / (x[i + 1] - x[i - 1]);
    const double r = y[i] - ((1.0 - t) * y[i - 1] + t * y[i + 1]);
    z.push_back(std::abs(r) / std::sqrt(1.0 + (1.0 - t) * (1.0 - t) + t * t));
  }
  return z.empty() ? 0.0 : kMadToSigma * median(z);
}

std::vector<double> running_median3(const std::vector<double>& v) {
  std::vector<double> s = v;
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    s[i] = std::max(std::min(v[i - 1], v[i]), std::min(std::max(v[i - 1], v[i]), v[i + 1]));
  return s;
}

// The fit points of a curve in log variables.
struct LogCurve {
  std::vector<std::size_t> index;  // into curve.points
  std::vector<double> x;           // ln tau
  std::vector<double> y;           // ln gamma_dot
  std::vector<double> e;           // ln eta = x - y
  std::vector<double> sigma;       // of y
};

LogCurve fit_points(const FlowCurve& curve, const AnalysisSettings& s, double& noise) {
  LogCurve c;
  bool errors_known = true;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    const FlowPoint& p = curve.points[i];
    if (!p.valid || p.jammed || !(p.shear_rate > 0.0)) continue;
    c.index.push_back(i);
    c.x.push_back(std::log(p.shear_stress));
    c.y.push_back(std::log(p.shear_rate));
    c.e.push_back(c.x.back() - c.y.back());
    errors_known = errors_known && p.shear_rate_err > 0.0;
    c.sigma.push_back(std::max(p.shear_rate_err / p.shear_rate, s.noise_floor));
  }
  if (c.index.empty()) return c;
  if (errors_known) {
    noise = median(c.sigma);
  } else {
    noise = std::max(scatter_about_neighbours(c.x, c.y), s.noise_floor);
    std::fill(c.sigma.begin(), c.sigma.end(), noise);
  }
  return c;
}

template <class T>
std::vector<T> slice(const std::vector<T>& v, std::size_t from, std::size_t to) {
  return {v.begin() + static_cast<long>(from), v.begin() + static_cast<long>(to)};
}

PolynomialFit fit_range(const LogCurve& c, std::size_t from, std::size_t to, int degree) {
  return fit_polynomial(slice(c.x, from, to), slice(c.y, from, to), slice(c.sigma, from, to),
                        degree);
}

// Step 4: the top points, grown down towards `onset`: the largest window whose
// quadratic term stays within kCurvatureSigmas standard errors. Every start is
// tried (not only until the first failure) so that one noisy point near the top
// does not cut the window short.
std::size_t automatic_window_start(const LogCurve& c, std::size_t onset,
                                   const AnalysisSettings& s) {
  const std::size_t n = c.x.size();
  const std::size_t first =
      std::max(kMinFitPoints, static_cast<std::size_t>(std::max(s.min_window_points, 0)));
  std::size_t best = n - std::min(first, n - onset);
  for (std::size_t start = best; start-- > onset;) {
    const PolynomialFit quad = fit_range(c, start, n, 2);
    if (std::abs(quad.coefficients[2]) <= kCurvatureSigmas * std::sqrt(quad.covariance(2, 2)))
      best = start;
  }
  return best;
}

// Step 5: n and its interval from the window [from, to).
void fit_exponent(const FlowCurve& curve, const LogCurve& c, std::size_t from, std::size_t to,
                  const AnalysisSettings& s, CurveResult& r) {
  const PolynomialFit line = fit_range(c, from, to, 1);
  const double b = line.coefficients[1];
  const double dof = static_cast<double>(line.dof());
  const double scale = dof > 0 ? std::max(1.0, line.chi2 / dof) : 1.0;
  const double se = std::sqrt(line.covariance(1, 1) * scale);
  const double t = student_t_quantile(0.5 + 0.5 * s.confidence, std::max(dof, 1.0));
  const auto exponent = [](double slope) { return slope > 0.0 ? 1.0 / slope - 1.0 : kInfinity; };
  r.n = exponent(b);
  r.n_low = exponent(b + t * se);
  r.n_high = exponent(b - t * se);
  r.n_sigma = b > 0.0 ? se / (b * b) : kInfinity;
  // ln gamma_dot = a + b ln tau  <=>  eta = K gamma_dot^n with ln K = -a/b.
  const double a = line.coefficients[0] - b * line.x0;
  if (b > 0.0) r.consistency = std::exp(-a / b);
  r.window_points = to - from;
  r.window_stress_low = curve.points[c.index[from]].shear_stress;
  r.window_stress_high = curve.points[c.index[to - 1]].shear_stress;
  for (std::size_t k = from; k < to; ++k) r.in_window[c.index[k]] = true;
}

// Rule 6's rate_falls: is there a fit point k at or above the onset whose rate is
// lower than the one before it (k - 1, at a lower stress) by more than their
// combined noise can explain? Under imposed stress the rate of an S-shaped flow
// curve (Wyart & Cates, PRL 112, 098302 (2014), Eq. 5; Mari, Seto, Morris &
// Denn, PRE 91, 052302 (2015), Fig. 1) falls where the stress passes the
// branch's turning point: a ramp that steps across it lands on the frictional
// branch at a lower rate. One such step is DST even where a power law over the
// window still has a finite n. The m steps are tested together (Bonferroni):
// each one-sided at kRateFallFalseCalls/m, so a curve whose rate never falls is
// called DST by this rule with probability at most kRateFallFalseCalls, however
// many points it has.
// Returns the fit point whose rate fell the most (in units of its step's
// combined noise) when that fall passes the threshold, else nothing.
std::optional<std::size_t> rate_falls(const LogCurve& c, std::size_t onset) {
  // One pass: the m steps and the largest fall in units of its combined noise;
  // the threshold z depends on m, so the comparison comes after.
  std::size_t steps = 0, largest_at = 0;
  double largest = -kInfinity;
  for (std::size_t k = std::max<std::size_t>(onset, 1); k < c.x.size(); ++k) {
    if (!(c.x[k] > c.x[k - 1])) continue;  // equal stresses: no order to read
    ++steps;
    const double fall = (c.y[k - 1] - c.y[k]) / std::hypot(c.sigma[k], c.sigma[k - 1]);
    if (fall > largest) {
      largest = fall;
      largest_at = k;
    }
  }
  if (steps == 0) return std::nullopt;
  const double z =
      student_t_quantile(1.0 - kRateFallFalseCalls / static_cast<double>(steps), kNormalDof);
  if (!(largest > z)) return std::nullopt;
  return largest_at;
}

// d ln eta / d ln gamma_dot at each fit point, from its neighbours (header, "Local slope").
void local_slopes(const LogCurve& c, CurveResult& r) {
  const std::size_t n = c.x.size();
  if (n < 2) return;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t left = k > 0 ? k - 1 : 0, right = k + 1 < n ? k + 1 : n - 1;
    if (!(c.x[right] > c.x[left])) continue;  // equal stresses: no slope
    const double b = (c.y[right] - c.y[left]) / (c.x[right] - c.x[left]);
    r.local_slope[c.index[k]] = b > 0.0 ? 1.0 / b - 1.0 : kInfinity;
  }
}

// The window the user set, as [from, to) in fit points.
std::pair<std::size_t, std::size_t> user_window(const FlowCurve& curve, const LogCurve& c) {
  const StressWindow& w = *curve.window;
  std::size_t from = c.x.size(), to = 0;
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    const double tau = curve.points[c.index[k]].shear_stress;
    if (tau < w.low || tau > w.high) continue;
    from = std::min(from, k);
    to = k + 1;
  }
  if (to < from + kMinFitPoints)
    throw InputError(fmt::format("{} = [{}, {}]: holds {} fitted points of {}; need at least {}",
                                 w.origin, w.low, w.high, to > from ? to - from : 0, curve.source,
                                 kMinFitPoints));
  return {from, to};
}

}  // namespace

std::string_view regime_name(Regime r) {
  switch (r) {
    case Regime::Newtonian:
      return "newtonian";
    case Regime::Cst:
      return "cst";
    case Regime::Dst:
      return "dst";
    case Regime::Unresolved:
      return "unresolved";
    case Regime::Jammed:
      return "jammed";
  }
  return "";
}

bool bagnold_holds(double n_low, double n_high, const AnalysisSettings& s) {
  const double f = s.bagnold_resolution;
  return n_low <= 1.0 && 1.0 <= n_high && n_low > 1.0 / f && n_high < f;
}

std::string_view dst_evidence_name(DstEvidence e) {
  switch (e) {
    case DstEvidence::None:
      return "";
    case DstEvidence::RateNotIncreasing:
      return "rate_not_increasing";
    case DstEvidence::ExponentAboveCap:
      return "n_above_cap";
    case DstEvidence::RateFalls:
      return "rate_falls";
    case DstEvidence::Jammed:
      return "jammed";
  }
  return "";
}

CurveResult analyse_curve(const FlowCurve& curve, const AnalysisSettings& s) {
  CurveResult r;
  // Step 8, on every flowing point (frac_bl is counted, not fitted).
  if (const auto contacts = contact_onset(curve)) {
    r.contact_onset_stress = contacts->stress;
    r.contact_onset_rate = contacts->rate;
    r.frac_bl_min = contacts->frac_bl_min;
  }
  r.in_window.assign(curve.points.size(), false);
  r.local_slope.assign(curve.points.size(), kNotFound);
  const auto is_jammed = [](const FlowPoint& p) { return p.jammed; };
  const bool jammed = std::any_of(curve.points.begin(), curve.points.end(), is_jammed);
  const bool never_flows =
      !curve.points.empty() && std::all_of(curve.points.begin(), curve.points.end(), is_jammed);
  const LogCurve c = fit_points(curve, s, r.noise);
  local_slopes(c, r);
  const std::size_t n = c.x.size();
  if (n < kMinFitPoints) {
    // Too few points for a plateau or an onset; a jam, or a rate that falls as
    // the stress rises (rule 6 over every step: a Newtonian or thickening flow
    // never does that), is still DST.
    r.regime = never_flows ? Regime::Jammed : jammed ? Regime::Dst : Regime::Unresolved;
    if (r.regime == Regime::Dst) r.dst_evidence = DstEvidence::Jammed;
    const auto fall = rate_falls(c, 0);
    if (fall) r.fall_stress = curve.points[c.index[*fall]].shear_stress;
    if (fall && r.regime == Regime::Unresolved) {
      r.regime = Regime::Dst;
      r.dst_evidence = DstEvidence::RateFalls;
    }
    return r;
  }

  // Steps 2-3: plateau and onset on the smoothed ln eta.
  const std::vector<double> smooth = running_median3(c.e);
  const auto bottom =
      static_cast<std::size_t>(std::min_element(smooth.begin(), smooth.end()) - smooth.begin());
  const auto first_above = [&](double level) {
    std::size_t k = bottom + 1;
    while (k < n && smooth[k] <= level) ++k;
    return k;
  };
  const double tolerance = kPlateauSigmas * r.noise;
  const std::size_t rough_onset = first_above(smooth[bottom] + std::log(s.onset_factor));
  std::vector<double> plateau;
  for (std::size_t k = 0; k < rough_onset; ++k)
    if (smooth[k] <= smooth[bottom] + tolerance) plateau.push_back(c.e[k]);
  r.eta_newtonian = std::exp(median(plateau));
  const double threshold = std::log(s.onset_factor * r.eta_newtonian);
  const std::size_t onset = first_above(threshold);

  if (onset < n) {
    double x_onset = c.x[onset];
    const double below = smooth[onset - 1];
    if (below < threshold)
      x_onset = c.x[onset - 1] +
                (threshold - below) / (smooth[onset] - below) * (c.x[onset] - c.x[onset - 1]);
    r.onset_stress = std::exp(x_onset);
    r.onset_rate = r.onset_stress / (s.onset_factor * r.eta_newtonian);
  }

  if (curve.window) {
    const auto [from, to] = user_window(curve, c);
    r.window_from_user = true;
    fit_exponent(curve, c, from, to, s, r);
  } else if (onset < n && n - onset >= kMinFitPoints) {
    fit_exponent(curve, c, automatic_window_start(c, onset, s), n, s, r);
  }

  // Step 6: the regime. Where the rate fell is reported whichever rule decides.
  const auto fall = onset < n ? rate_falls(c, onset) : std::nullopt;
  if (fall) r.fall_stress = curve.points[c.index[*fall]].shear_stress;
  if (jammed) {
    r.regime = Regime::Dst;
    r.dst_evidence = DstEvidence::Jammed;
  } else if (onset >= n) {
    r.regime = Regime::Newtonian;
  } else if (r.window_points > 0 && std::isinf(r.n)) {
    r.regime = Regime::Dst;
    r.dst_evidence = DstEvidence::RateNotIncreasing;
  } else if (r.window_points > 0 && r.n > s.dst_n_cap) {
    r.regime = Regime::Dst;
    r.dst_evidence = DstEvidence::ExponentAboveCap;
  } else if (fall) {
    r.regime = Regime::Dst;
    r.dst_evidence = DstEvidence::RateFalls;
  } else if (r.window_points == 0) {
    r.regime = Regime::Unresolved;
  } else {
    r.regime = Regime::Cst;
    // Step 7: Bagnold scaling, n = 1, within the interval.
    r.bagnold = bagnold_holds(r.n_low, r.n_high, s);
  }
  return r;
}

}  // namespace dilatant::analysis
