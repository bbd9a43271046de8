#include "analysis/wyart_cates_prediction.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "dilatant/version.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kUnknownError = std::numeric_limits<double>::quiet_NaN();
// As the table's predictor (jamming_table.hpp): closer than this to a
// boundary, the regime is uncertain.
constexpr double kUncertainSigmas = 2.0;

Json or_null_value(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json read_model_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot read the model file", file.string()));
  std::stringstream text;
  text << in.rdbuf();
  Json j = Json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("samples") || !j["samples"].is_object() ||
      j.value("model", "").find("phi_J") == std::string::npos)
    throw InputError(
        fmt::format("{}: not a Wyart-Cates fit (the wyart_cates.json of `dilatant analyze --model "
                    "wyart-cates`)",
                    file.string()));
  return j;
}

double required_number(const Json& sample, const std::string& key,
                       const std::filesystem::path& file, const std::string& name) {
  if (!sample.contains(key) || !sample[key].is_number())
    throw InputError(
        fmt::format("{}: sample {}: '{}' is missing or not a number", file.string(), name, key));
  return sample[key].get<double>();
}

double number_or_nan(const Json& j, const std::string& key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : kUnknownError;
}

// A fit of one suspension's seeds (wyart_cates_seeds.hpp) holds the seeds'
// fits and their pooled one: the pooled one answers unless a sample is chosen.
// Empty when the fitted samples are anything else.
std::string the_pooled_sample(const Json& j, const std::vector<std::string>& fitted) {
  for (const std::string& name : fitted) {
    const Json& s = j["samples"][name];
    if (!s.contains("seeds") || !s["seeds"].contains("members")) continue;
    const Json& members = s["seeds"]["members"];
    const bool all_members = std::all_of(fitted.begin(), fitted.end(), [&](const std::string& f) {
      return f == name || std::find(members.begin(), members.end(), f) != members.end();
    });
    if (all_members) return name;
  }
  return {};
}

}  // namespace

std::vector<std::string> fitted_wyart_cates_samples(const std::filesystem::path& file) {
  const Json j = read_model_file(file);
  std::vector<std::string> names;
  for (const auto& [name, s] : j["samples"].items())
    if (s.value("fitted", false)) names.push_back(name);
  return names;
}

FittedWyartCates read_fitted_wyart_cates(const std::filesystem::path& file,
                                         const std::string& sample,
                                         const std::string& sample_option) {
  const Json j = read_model_file(file);
  const std::vector<std::string> fitted = fitted_wyart_cates_samples(file);
  std::string name = sample;
  if (name.empty()) {
    // A pooled fit that failed: one seed's fit must not answer for the
    // suspension unasked.
    for (const auto& [pooled, entry] : j["samples"].items())
      if (entry.contains("seeds") && !entry.value("fitted", false))
        throw InputError(fmt::format(
            "{}: the pooled fit of the seeds ({}) failed ({}); choose a seed's fit with {}",
            file.string(), pooled, entry.value("fit_note", "no reason given"), sample_option));
    name = the_pooled_sample(j, fitted);
  }
  if (name.empty()) {
    if (fitted.size() != 1)
      throw InputError(
          fmt::format("{}: {} fitted samples{}; choose one with {}", file.string(), fitted.size(),
                      fitted.empty() ? "" : " (" + fmt::format("{}", fmt::join(fitted, ", ")) + ")",
                      sample_option));
    name = fitted.front();
  }
  if (!j["samples"].contains(name))
    throw InputError(fmt::format("{} {}: no such sample in {} (fitted: {})", sample_option, name,
                                 file.string(), fmt::join(fitted, ", ")));
  const Json& s = j["samples"][name];
  if (!s.value("fitted", false))
    throw InputError(fmt::format("{} {}: not fitted in {} ({})", sample_option, name, file.string(),
                                 s.value("fit_note", "no reason given")));
  FittedWyartCates f;
  f.file = file.string();
  f.sample = name;
  f.model = {required_number(s, "phi_0", file, name),      required_number(s, "phi_m", file, name),
             required_number(s, "sigma_star", file, name), required_number(s, "A", file, name),
             required_number(s, "alpha", file, name),      required_number(s, "beta", file, name)};
  f.phi_0 = {f.model.phi_0, number_or_nan(s, "phi_0_err")};
  f.phi_m = {f.model.phi_m, number_or_nan(s, "phi_m_err")};
  // phi_DST is recomputed from the parameters (not trusted from the file);
  // its error is the fit's.
  f.phi_dst = {dst_onset(f.model).phi,
               s.contains("dst") ? number_or_nan(s["dst"], "phi_dst_err") : kUnknownError};
  // A pooled fit of several seeds: its errors come from the residuals of
  // packings pooled together, which understate the scatter between packings
  // (docs/wyart-cates.md "Seeds"); the boundaries' errors are the larger of
  // the fit's and the seeds' standard error.
  if (s.contains("seeds") && s["seeds"].contains("spread")) {
    const Json& spread = s["seeds"]["spread"];
    for (auto [key, e] :
         {std::pair{"phi_0", &f.phi_0}, {"phi_m", &f.phi_m}, {"phi_dst", &f.phi_dst}})
      if (spread.contains(key)) {
        const double sem = number_or_nan(spread[key], "sem");
        if (std::isfinite(sem) && !(e->err >= sem)) e->err = sem;
      }
    f.errors = "the larger of the pooled fit's and the seeds' standard error";
  }
  f.units = j.value("units", Json::object());
  f.phi_basis = s.value("phi_basis", "nominal");
  if (f.phi_basis != "bulk" && f.phi_basis != "nominal")
    throw InputError(fmt::format("{}: sample {}: phi_basis '{}' is neither bulk nor nominal",
                                 file.string(), name, f.phi_basis));
  return f;
}

Json wyart_cates_prediction(const FittedWyartCates& fit, double phi, std::optional<double> stress) {
  const WyartCatesParameters& p = fit.model;
  Json j;
  j["source"] = "wyart-cates fit";
  j["model_file"] = fit.file;
  j["sample"] = fit.sample;
  j["phi"] = phi;
  j["phi_basis"] = fit.phi_basis;
  j["regime"] = flow_curve_regime(p, phi);
  j["phi_dst"] = or_null_value(fit.phi_dst.value);
  j["phi_dst_err"] = or_null_value(fit.phi_dst.err);
  j["phi_m"] = or_null_value(fit.phi_m.value);
  j["phi_m_err"] = or_null_value(fit.phi_m.err);
  j["phi_0"] = or_null_value(fit.phi_0.value);
  j["phi_0_err"] = or_null_value(fit.phi_0.err);
  j["errors"] = fit.errors;
  double margin = std::numeric_limits<double>::infinity();
  for (const Estimate& b : {fit.phi_dst, fit.phi_m, fit.phi_0})
    if (std::isfinite(b.value) && b.err > 0.0)
      margin = std::min(margin, std::abs(phi - b.value) / b.err);
  j["margin_sigma"] = or_null_value(margin);
  j["uncertain"] = margin < kUncertainSigmas;
  j["sigma_star"] = p.sigma_star;
  const TurningRange t = turning_range(p, phi);
  j["turning_range"] = t.exists() ? Json::array({t.low, t.high}) : Json(nullptr);
  j["shear_jamming_stress"] = or_null_value(shear_jamming_stress(p, phi));
  if (stress) {
    const double eta = wyart_cates_viscosity(p, phi, *stress);
    j["stress"] = *stress;
    j["state"] = flow_state_name(flow_state(p, phi, *stress));
    j["viscosity"] = or_null_value(eta);
    j["shear_rate"] = std::isfinite(eta) ? Json(*stress / eta) : Json(0.0);
    j["frictional_fraction"] = frictional_fraction(p, *stress);
    j["phi_j"] = jamming_fraction(p, *stress);
  }
  j["units"] = fit.units;
  j["version"] = kVersion;
  return j;
}

}  // namespace dilatant::analysis
