#include "analysis/wyart_cates_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "dilatant/version.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"

namespace dilatant::analysis {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kNoOnset = std::numeric_limits<double>::quiet_NaN();
// The model lines of the overlay extend a factor 3 beyond the data's stresses.
constexpr double kOverlayMargin = 3.0;
constexpr int kOverlayNodes = 121;
// The map runs from 0.03 below phi_DST (or the smallest measured phi) to phi_0.
constexpr double kMapBelow = 0.03;
constexpr int kMapNodes = 161;

Json or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }
std::string csv_cell(double v) {
  return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string();
}

// phi_DST depends on phi_0, phi_m, alpha and beta (not on sigma* or A:
// wyart_cates_model.hpp); its variance is g^T C g with g its gradient in the
// fitted ones, by central differences.
double onset_phi_error(const WyartCatesFit& fit) {
  const WyartCatesParameters p = fit.model();
  const auto n = static_cast<Eigen::Index>(fit.names.size());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::string& name = fit.names[static_cast<std::size_t>(k)];
    double WyartCatesParameters::*field = name == "phi_0"   ? &WyartCatesParameters::phi_0
                                          : name == "phi_m" ? &WyartCatesParameters::phi_m
                                          : name == "alpha" ? &WyartCatesParameters::alpha
                                          : name == "beta"  ? &WyartCatesParameters::beta
                                                            : nullptr;
    if (!field) continue;  // sigma*, A: phi_DST does not depend on them
    const double h = 1e-5 * std::max(1.0, std::abs(p.*field));
    WyartCatesParameters up = p, down = p;
    up.*field += h;
    down.*field -= h;
    g[k] = (dst_onset(up).phi - dst_onset(down).phi) / (2.0 * h);
  }
  const double var = g.dot(fit.covariance * g);
  return var >= 0.0 ? std::sqrt(var) : kNoOnset;
}

std::string regime_at(const WyartCatesParameters& p, const DstOnset& onset, double phi) {
  if (!(p.phi_m < p.phi_0)) return phi < p.phi_0 ? "cst" : "no_flow";
  if (phi >= p.phi_0) return "no_flow";
  if (phi >= p.phi_m) return "shear_jamming";
  return phi < onset.phi ? "cst" : "dst";
}

Json unit_names(UnitSystem u) {
  if (u == UnitSystem::SI) return {{"shear_stress", "Pa"}, {"viscosity", "Pa s"}};
  return {{"shear_stress", "eta_f^2/(rho_p R^2)"}, {"viscosity", "eta_f"}};
}

void put_estimate(Json& j, const char* name, const Estimate& e) {
  j[name] = or_null(e.value);
  j[std::string(name) + "_err"] = or_null(e.err);
}

// An exponent's value, error (null when held) and whether it was fitted.
void put_exponent(Json& j, const char* name, const Estimate& e, const WyartCatesFit& f) {
  put_estimate(j, name, e);
  const bool fitted = std::find(f.names.begin(), f.names.end(), name) != f.names.end();
  j[std::string(name) + "_source"] = fitted ? "fitted" : "fixed";
}

Json seeds_json(const WyartCatesSample& s) {
  Json j;
  j["members"] = s.members;
  j["note"] =
      "each member fitted alone (its own entry in samples); mean, sd (n - 1) and sem = "
      "sd/sqrt(n) over those with a fit (phi_dst: those with a DST boundary)";
  Json spread = Json::object();
  for (const SeedSpread& q : s.seed_spreads)
    spread[q.name] = {
        {"n", q.n}, {"mean", or_null(q.mean)}, {"sd", or_null(q.sd)}, {"sem", or_null(q.sem)}};
  j["spread"] = spread;
  return j;
}

Json wyart_cates_sample_json(const WyartCatesSample& s) {
  Json j;
  j["curves"] = s.curves;
  if (!s.members.empty()) j["seeds"] = seeds_json(s);
  if (!s.outcome.fit) {
    j["fitted"] = false;
    j["fit_note"] = s.outcome.why_not;
    return j;
  }
  const WyartCatesFit& f = *s.outcome.fit;
  j["fitted"] = true;
  put_estimate(j, "phi_0", f.phi_0);
  put_estimate(j, "phi_m", f.phi_m);
  put_estimate(j, "sigma_star", f.sigma_star);
  put_estimate(j, "A", f.A);
  put_exponent(j, "alpha", f.alpha, f);
  put_exponent(j, "beta", f.beta, f);
  j["chi2_per_dof"] = or_null(f.chi2_per_dof());
  j["rms_log10_deviation"] = or_null(f.rms_log10_deviation);
  j["weights"] = f.weighted ? "the errors of eta (gamma_dot_err, or eta_err at an imposed rate)"
                            : "uniform in ln eta; the scatter is measured from the residuals";
  j["fitted_points"] = f.points;
  j["fitted_curves"] = f.curves;
  j["phi_basis"] = f.phi_bulk ? "bulk" : "nominal";
  j["phi"] = f.phi;
  j["stress_range"] = {f.stress_low, f.stress_high};
  Json corr = Json::object();
  for (std::size_t a = 0; a < f.names.size(); ++a) {
    Json row = Json::object();
    for (std::size_t b = 0; b < f.names.size(); ++b) {
      const auto ia = static_cast<Eigen::Index>(a), ib = static_cast<Eigen::Index>(b);
      row[f.names[b]] =
          or_null(f.covariance(ia, ib) / std::sqrt(f.covariance(ia, ia) * f.covariance(ib, ib)));
    }
    corr[f.names[a]] = row;
  }
  j["correlation"] = corr;
  const WyartCatesParameters p = f.model();
  Json dst;
  dst["phi_dst"] = or_null(s.onset.phi);
  dst["phi_dst_err"] = or_null(s.onset_phi_err);
  dst["onset_stress"] = or_null(s.onset.stress);
  dst["phi_m"] = or_null(p.phi_m);
  dst["phi_0"] = or_null(p.phi_0);
  dst["regimes"] = p.phi_m < p.phi_0
                       ? "cst below phi_dst; dst (the stress-controlled curve turns back) from "
                         "phi_dst to phi_m; shear_jamming (jams above sigma_SJ(phi)) from "
                         "phi_m to phi_0; no_flow above phi_0"
                       : "phi_m >= phi_0: no thickening, no DST";
  j["dst"] = dst;
  return j;
}

WyartCatesSample fitted_sample(std::string name, const std::vector<FlowCurve>& curves,
                               const WyartCatesSettings& settings) {
  WyartCatesSample s;
  s.sample = std::move(name);
  s.curves = curves.size();
  s.outcome = fit_wyart_cates(curves, settings);
  s.onset = {kNoOnset, kNoOnset};
  s.onset_phi_err = kNoOnset;
  if (s.outcome.fit) {
    s.onset = dst_onset(s.outcome.fit->model());
    s.onset_phi_err = onset_phi_error(*s.outcome.fit);
  }
  return s;
}

// The scatter of the seeds' own fits: each parameter the fit varied, and phi_DST.
std::vector<SeedSpread> spreads_over(const std::vector<const WyartCatesSample*>& seeds,
                                     const WyartCatesSettings& settings) {
  std::vector<std::pair<const char*, double (*)(const WyartCatesSample&)>> quantities = {
      {"phi_0", [](const WyartCatesSample& s) { return s.outcome.fit->phi_0.value; }},
      {"phi_m", [](const WyartCatesSample& s) { return s.outcome.fit->phi_m.value; }},
      {"sigma_star", [](const WyartCatesSample& s) { return s.outcome.fit->sigma_star.value; }},
      {"A", [](const WyartCatesSample& s) { return s.outcome.fit->A.value; }}};
  if (settings.fit_alpha)
    quantities.push_back(
        {"alpha", [](const WyartCatesSample& s) { return s.outcome.fit->alpha.value; }});
  if (settings.fit_beta)
    quantities.push_back(
        {"beta", [](const WyartCatesSample& s) { return s.outcome.fit->beta.value; }});
  quantities.push_back({"phi_dst", [](const WyartCatesSample& s) { return s.onset.phi; }});
  std::vector<SeedSpread> out;
  for (const auto& [name, value] : quantities) {
    std::vector<double> values;
    for (const WyartCatesSample* s : seeds)
      if (s->outcome.fit && std::isfinite(value(*s))) values.push_back(value(*s));
    out.push_back(seed_spread(name, values));
  }
  return out;
}

}  // namespace

bool WyartCatesSample::holds(const std::string& curve_sample) const {
  if (members.empty()) return curve_sample == sample;
  return std::find(members.begin(), members.end(), curve_sample) != members.end();
}

bool WyartCatesReport::any_fit() const {
  for (const auto& s : samples)
    if (s.outcome.fit) return true;
  return false;
}

WyartCatesReport wyart_cates_report(const AnalysisInput& input,
                                    const WyartCatesSettings& settings) {
  WyartCatesReport r;
  r.source = input.source;
  r.kind = input.kind;
  r.units = input.units;
  r.settings = settings;
  // "auto" decided once for the whole input, so that seeds and their pool are
  // fitted in the same fraction: bulk only if every fitted point has one.
  WyartCatesSettings resolved = settings;
  if (settings.phi == WyartCatesSettings::Phi::Auto)
    resolved.phi = every_fitted_point_has_bulk(input.curves) ? WyartCatesSettings::Phi::Bulk
                                                             : WyartCatesSettings::Phi::Nominal;
  r.curves = input.curves;
  std::stable_sort(r.curves.begin(), r.curves.end(),
                   [](const FlowCurve& a, const FlowCurve& b) { return a.phi < b.phi; });
  for (const std::string& name : input.samples) {
    std::vector<FlowCurve> mine;
    for (const FlowCurve& c : input.curves)
      if (c.sample == name) mine.push_back(c);
    r.samples.push_back(fitted_sample(name, mine, resolved));
  }
  for (const SeedGroup& g : seed_groups(input.samples)) {
    std::vector<FlowCurve> mine;
    for (const FlowCurve& c : input.curves)
      if (std::find(g.members.begin(), g.members.end(), c.sample) != g.members.end())
        mine.push_back(c);
    const bool taken =
        std::find(input.samples.begin(), input.samples.end(), g.label) != input.samples.end();
    WyartCatesSample pooled =
        fitted_sample(taken ? g.label + " (seeds pooled)" : g.label, mine, resolved);
    pooled.members = g.members;
    std::vector<const WyartCatesSample*> seeds;
    for (const auto& s : r.samples)
      if (pooled.holds(s.sample)) seeds.push_back(&s);
    pooled.seed_spreads = spreads_over(seeds, settings);
    r.samples.push_back(std::move(pooled));
  }
  return r;
}

std::string wyart_cates_json(const WyartCatesReport& r) {
  Json j;
  j["version"] = kVersion;
  j["input"] = r.source;
  j["kind"] = r.kind == InputKind::Manifest ? "manifest" : "sweep_table";
  j["units"] = unit_names(r.units);
  j["model"] =
      "eta = A (1 - phi/phi_J)^(-alpha), phi_J = f phi_m + (1 - f) phi_0, "
      "f = exp(-(sigma_star/sigma)^beta); A includes the solvent viscosity";
  j["references"] = {"Wyart & Cates, PRL 112, 098302 (2014)",
                     "Singh, Mari, Denn & Morris, J. Rheol. 62, 457 (2018)"};
  j["settings"] = {{"alpha", r.settings.alpha},
                   {"fit_alpha", r.settings.fit_alpha},
                   {"beta", r.settings.beta},
                   {"fit_beta", r.settings.fit_beta},
                   {"noise_floor", r.settings.noise_floor},
                   {"phi", phi_basis_name(r.settings.phi)},
                   {"weights", weights_name(r.settings.weights)}};
  Json samples = Json::object();
  for (const auto& s : r.samples) samples[s.sample] = wyart_cates_sample_json(s);
  j["samples"] = samples;
  return j.dump(2) + "\n";
}

std::string wyart_cates_curves_csv(const WyartCatesReport& r) {
  std::string out = "sample,phi,kind,shear_stress,shear_rate,viscosity,fitted\n";
  for (const auto& s : r.samples) {
    std::vector<double> drawn;  // a pooled sample's model line once per phi
    const bool bulk = s.outcome.fit && s.outcome.fit->phi_bulk;
    for (const FlowCurve& c : r.curves) {
      if (!s.holds(c.sample)) continue;
      // In the fit's terms: a curve fitted in its bulk fraction is labelled,
      // and its model line drawn, at the mean of its points' (fitted_phi).
      const double phi = fitted_phi(c, bulk);
      for (const FlowPoint& p : c.points)
        out += fmt::format("{},{},data,{},{},{},{}\n", s.sample, csv_cell(phi),
                           csv_cell(p.shear_stress), csv_cell(p.shear_rate), csv_cell(p.viscosity),
                           wyart_cates_fits_point(p));
      if (!s.outcome.fit || std::find(drawn.begin(), drawn.end(), phi) != drawn.end()) continue;
      drawn.push_back(phi);
      const WyartCatesFit& f = *s.outcome.fit;
      const WyartCatesParameters m = f.model();
      const double lo = f.stress_low / kOverlayMargin, hi = f.stress_high * kOverlayMargin;
      for (int k = 0; k < kOverlayNodes; ++k) {
        const double sigma = lo * std::pow(hi / lo, k / (kOverlayNodes - 1.0));
        const double eta = wyart_cates_viscosity(m, phi, sigma);
        if (!std::isfinite(eta)) break;  // jammed: the model curve ends
        out += fmt::format("{},{},model,{},{},{},false\n", s.sample, csv_cell(phi), csv_cell(sigma),
                           csv_cell(sigma / eta), csv_cell(eta));
      }
    }
  }
  return out;
}

std::string wyart_cates_map_csv(const WyartCatesReport& r) {
  std::string out = "sample,phi,regime,turn_low,turn_high,shear_jamming_stress\n";
  for (const auto& s : r.samples) {
    if (!s.outcome.fit) continue;
    const WyartCatesParameters p = s.outcome.fit->model();
    double low = s.outcome.fit->phi.front();
    if (std::isfinite(s.onset.phi)) low = std::min(low, s.onset.phi - kMapBelow);
    const double high = std::max(p.phi_0, s.outcome.fit->phi.back());
    for (int k = 0; k < kMapNodes; ++k) {
      const double phi = low + (high - low) * k / (kMapNodes - 1.0);
      const TurningRange t = turning_range(p, phi);
      out += fmt::format("{},{:.6f},{},{},{},{}\n", s.sample, phi, regime_at(p, s.onset, phi),
                         csv_cell(t.low), csv_cell(t.high), csv_cell(shear_jamming_stress(p, phi)));
    }
  }
  return out;
}

void write_wyart_cates_files(const WyartCatesReport& report, const std::filesystem::path& dir) {
  write_file_atomically(dir / "wyart_cates.json", wyart_cates_json(report));
  write_file_atomically(dir / "wyart_cates_curves.csv", wyart_cates_curves_csv(report));
  write_file_atomically(dir / "wyart_cates_map.csv", wyart_cates_map_csv(report));
}

void remove_wyart_cates_files(const std::filesystem::path& dir) {
  remove_earlier_results(dir, {"wyart_cates.json", "wyart_cates_curves.csv", "wyart_cates_map.csv",
                               "wyart_cates.png", "wyart_cates.svg"});
}

}  // namespace dilatant::analysis
