#include "analysis/report_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "dilatant/version.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"

namespace dilatant::analysis {
namespace {

using Json = nlohmann::ordered_json;

// Empty for "not applicable" (NaN), "inf" for a divergent exponent.
std::string csv(double v) {
  if (std::isnan(v)) return "";
  return fmt::format("{:.6g}", v);
}

// Text for a quoted CSV field: '"' doubled (RFC 4180).
std::string csv_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    out.push_back(c);
    if (c == '"') out.push_back('"');
  }
  return out;
}

// null when not available (nlohmann writes NaN and inf as null too; explicit here).
Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json units(UnitSystem u) {
  if (u == UnitSystem::SI)
    return {{"shear_stress", "Pa"}, {"shear_rate", "1/s"}, {"viscosity", "Pa s"}};
  return {{"shear_stress", "eta_f^2/(rho_p R^2)"},
          {"shear_rate", "eta_f/(rho_p R^2)"},
          {"viscosity", "eta_f"}};
}

Json settings(const AnalysisSettings& s) {
  return {{"onset_factor", s.onset_factor},
          {"dst_n_cap", s.dst_n_cap},
          {"min_window_points", s.min_window_points},
          {"confidence", s.confidence},
          {"noise_floor", s.noise_floor}};
}

// A, alpha (and, for one series, phi_max) of a fit, flat.
void put_fit(Json& j, const DivergenceFit& f) {
  j["A"] = number(f.A.value);
  j["A_err"] = number(f.A.err);
  j["alpha"] = number(f.alpha.value);
  j["alpha_err"] = number(f.alpha.err);
  j["chi2_per_dof"] = number(f.chi2_per_dof());
  j["fitted_curves"] = f.points;
}

Json sample_json(const SampleReport& s) {
  Json j;
  j["curves"] = s.curves;
  j["cst_curves"] = s.cst_curves;
  j["dst_curves"] = s.dst_curves;
  j["dst_phi_min"] = number(s.dst_phi_min);
  const auto& fit = s.fit.fit;
  if (s.phi_max_given) {
    j["phi_max"] = *s.phi_max_given;
    j["phi_max_err"] = nullptr;
    j["phi_max_source"] = "given";
  } else {
    j["phi_max"] = fit ? number(fit->phi_max[0].value) : Json(nullptr);
    j["phi_max_err"] = fit ? number(fit->phi_max[0].err) : Json(nullptr);
    j["phi_max_source"] = fit ? "fitted" : "unavailable";
  }
  if (fit) {
    put_fit(j, *fit);
  } else {
    for (const char* k : {"A", "A_err", "alpha", "alpha_err", "chi2_per_dof"}) j[k] = nullptr;
    j["fitted_curves"] = s.series.points.size();
    j["fit_note"] = s.fit.why_not;
  }
  if (s.phi_max_given) {
    if (const auto& free = s.free_fit.fit) {
      Json f;
      f["phi_max"] = number(free->phi_max[0].value);
      f["phi_max_err"] = number(free->phi_max[0].err);
      put_fit(f, *free);
      j["free_fit"] = f;
    } else {
      j["free_fit"] = nullptr;
      j["free_fit_note"] = s.free_fit.why_not;
    }
  }
  j["notes"] = s.notes;
  return j;
}

Json collapse_json(const AnalysisReport& r) {
  const CollapseReport& c = r.collapse;
  Json j;
  j["samples"] = c.samples;
  j["left_out"] = c.left_out;
  if (!c.fit.fit) {
    j["note"] = c.fit.why_not;
    return j;
  }
  const DivergenceFit& f = *c.fit.fit;
  put_fit(j, f);
  j["rms_log10_deviation"] = number(f.rms_log10_deviation);
  Json phi_max = Json::object();
  for (std::size_t k = 0; k < c.samples.size(); ++k) {
    const bool given = r.input.phi_max.count(c.samples[k]) > 0;
    phi_max[c.samples[k]] = {{"value", number(f.phi_max[k].value)},
                             {"err", number(f.phi_max[k].err)},
                             {"source", given ? "given" : "fitted"}};
  }
  j["phi_max"] = phi_max;
  return j;
}

}  // namespace

std::string curves_csv(const AnalysisReport& r) {
  std::string out =
      "sample,phi,eta_newtonian,onset_stress,onset_rate,n,n_low,n_high,regime,dst_evidence,"
      "fall_stress,bagnold,n_sigma,consistency,window_stress_low,window_stress_high,"
      "window_points,window,noise,points,file,step,dropped_rows,contact_onset_stress,"
      "contact_onset_rate,frac_bl_min\n";
  for (std::size_t i = 0; i < r.curves.size(); ++i) {
    const FlowCurve& c = r.input.curves[i];
    const CurveResult& k = r.curves[i];
    const bool fitted = k.window_points > 0;
    const char* bagnold = !k.bagnold ? "" : *k.bagnold ? "true" : "false";
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\",\"{}\",{},{},{},{}\n",
        c.sample, csv(c.phi), csv(k.eta_newtonian), csv(k.onset_stress), csv(k.onset_rate),
        csv(k.n), csv(k.n_low), csv(k.n_high), regime_name(k.regime),
        dst_evidence_name(k.dst_evidence), csv(k.fall_stress), bagnold, csv(k.n_sigma),
        csv(k.consistency), csv(k.window_stress_low), csv(k.window_stress_high), k.window_points,
        fitted ? (k.window_from_user ? "user" : "auto") : "", csv(k.noise), c.points.size(),
        csv_text(c.source), csv_text(c.step), c.dropped_rows, csv(k.contact_onset_stress),
        csv(k.contact_onset_rate), csv(k.frac_bl_min));
  }
  return out;
}

std::string points_csv(const AnalysisReport& r) {
  std::string out =
      "curve,sample,phi,shear_stress,shear_rate,viscosity,valid,jammed,in_window,local_slope\n";
  for (std::size_t i = 0; i < r.curves.size(); ++i) {
    const FlowCurve& c = r.input.curves[i];
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      const FlowPoint& p = c.points[k];
      out +=
          fmt::format("{},{},{},{},{},{},{},{},{},{}\n", i, c.sample, csv(c.phi),
                      csv(p.shear_stress), csv(p.shear_rate), csv(p.viscosity), p.valid, p.jammed,
                      static_cast<bool>(r.curves[i].in_window[k]), csv(r.curves[i].local_slope[k]));
    }
  }
  return out;
}

std::string fits_json(const AnalysisReport& r) {
  Json j;
  j["version"] = kVersion;
  j["input"] = r.input.source;
  j["kind"] = r.input.kind == InputKind::Manifest ? "manifest" : "sweep_table";
  j["units"] = units(r.input.units);
  j["model"] = "n - 1 = A * x^(-alpha), x = (phi_max - phi) / phi_max";
  j["settings"] = settings(r.settings);
  // Rows left out under the table policy (io/table_rows.hpp), per file.
  j["dropped_rows"] = r.input.dropped_rows;
  j["dropped"] = r.input.dropped;
  // Steps of the rheometer files that are not flow curves (rheometer_file.hpp).
  j["skipped_steps"] = r.input.skipped_steps;
  Json samples = Json::object();
  for (const auto& s : r.samples) samples[s.sample] = sample_json(s);
  j["samples"] = samples;
  j["collapse"] = collapse_json(r);
  return j.dump(2) + "\n";
}

void write_report_files(const AnalysisReport& report, const std::filesystem::path& dir) {
  prepare_output_folder(dir);
  write_file_atomically(dir / "curves.csv", curves_csv(report));
  write_file_atomically(dir / "points.csv", points_csv(report));
  write_file_atomically(dir / "fits.json", fits_json(report));
}

}  // namespace dilatant::analysis
