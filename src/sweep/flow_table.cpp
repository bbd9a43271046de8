#include "sweep/flow_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace dilatant::sweep {
namespace {

using namespace std::string_view_literals;

// summary.json fields copied as they are (phi is renamed phi_realized).
constexpr std::array kSummaryBefore = {"shear_stress"sv,   "gamma_dot"sv,
                                       "gamma_dot_err"sv,  "eta"sv,
                                       "eta_err"sv,        "valid"sv,
                                       "jammed"sv,         "frac_bl"sv,
                                       "frac_bl_err"sv,    "frac_hd"sv,
                                       "frac_over_slim"sv, "gamma_dot_bulk"sv,
                                       "gamma_dot_gap"sv,  "profile_consistent"sv,
                                       "steady"sv};
constexpr std::array kSummaryAfter = {"phi_bulk"sv,
                                      "phi_bulk_err"sv,
                                      "phi_box"sv,
                                      "s_c"sv,
                                      "friction_law"sv,
                                      "normal_stress"sv,
                                      "normal_stress_err"sv,
                                      "inertial_number"sv,
                                      "viscous_number"sv,
                                      "control"sv,
                                      "normal_stress_imposed"sv,
                                      "box_height_mean"sv,
                                      "box_height_err"sv,
                                      "box_height_fluctuation"sv,
                                      "phi_bulk_drift"sv,
                                      "phi_bulk_drift_err"sv,
                                      "shear_stress_measured"sv,
                                      "shear_stress_measured_err"sv,
                                      "pressure"sv,
                                      "pressure_err"sv,
                                      "n1"sv,
                                      "n1_err"sv,
                                      "n2"sv,
                                      "n2_err"sv,
                                      "mu_eff"sv,
                                      "mu_eff_err"sv,
                                      "mu_pressure"sv,
                                      "mu_pressure_err"sv,
                                      "mu_eff_definition"sv,
                                      "frac_impulsive"sv,
                                      "frac_bl_persistent"sv,
                                      "mobile_spheres"sv,
                                      "strain"sv,
                                      "steps"sv,
                                      "mean_iterations"sv,
                                      "frac_steps_unconverged"sv,
                                      "wall_time_s"sv,
                                      "version"sv};
// Swept keys that place a point along its curve or name the curve's own columns:
// a stress ramp sweeps fluid.lambda (or cell.shear_stress), a rate sweep under
// cell.control = "rate" sweeps cell.shear_rate; under cell.control =
// "pressure" the viscous number J = eta_f gamma_dot / P moves along mu(J),
// phi(J) by cell.shear_rate or cell.normal_stress (Boyer, Guazzelli &
// Pouliquen, PRL 107, 188301 (2011)); none of them names another curve.
constexpr std::array kCurveKeys = {"cell.phi"sv,        "friction.mu0"sv,
                                   "fluid.lambda"sv,    "cell.shear_stress"sv,
                                   "cell.shear_rate"sv, "cell.normal_stress"sv};

std::string field(std::string text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::replace(text.begin(), text.end(), '"', '\'');
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return "\"" + text + "\"";
}

std::string json_field(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return fmt::format("{}", v.get<std::int64_t>());
  if (v.is_number_unsigned()) return fmt::format("{}", v.get<std::uint64_t>());
  // Not finite: summary.json writes null, so the table leaves it empty too
  // (a summary taken from the run in memory must give the row its file gives).
  if (v.is_number_float())
    return std::isfinite(v.get<double>()) ? fmt::format("{}", v.get<double>()) : "";
  if (v.is_string()) return field(v.get<std::string>());
  return field(v.dump());
}

// A key of a JSON object (a summary, a cold start's), as a table field;
// empty when the object or the key is missing.
std::string member_field(const nlohmann::json& object, std::string_view key) {
  if (!object.is_object()) return "";
  const auto it = object.find(std::string(key));
  return it == object.end() ? "" : json_field(*it);
}

std::string summary_field(const PointRecord& r, std::string_view key) {
  return r.status == PointStatus::Done ? member_field(r.summary, key) : "";
}

}  // namespace

std::string_view status_name(PointStatus s) {
  switch (s) {
    case PointStatus::Done:
      return "done";
    case PointStatus::Failed:
      return "failed";
    case PointStatus::Skipped:
      return "skipped";
    case PointStatus::Pending:
    case PointStatus::Running:
      return "pending";
  }
  return "pending";
}

bool jammed(const PointRecord& r) {
  if (r.status != PointStatus::Done || !r.summary.is_object()) return false;
  const auto it = r.summary.find("jammed");
  return it != r.summary.end() && it->is_boolean() && it->get<bool>();
}

std::string sample_label(const SweepPlan& plan, const SweepPoint& point) {
  std::string label = fmt::format("mu0={}", point.config.friction.mu0);
  for (const auto& key : plan.keys) {
    if (std::find(kCurveKeys.begin(), kCurveKeys.end(), key) != kCurveKeys.end()) continue;
    const auto* value = find_key(point.config.resolved, key);
    label += fmt::format(" {}={}", key.substr(key.rfind('.') + 1), value ? plain_text(*value) : "");
  }
  std::replace(label.begin(), label.end(), ',', ';');
  std::replace(label.begin(), label.end(), '"', '\'');
  return label;
}

std::string flowcurves_csv(const SweepPlan& plan, const std::vector<PointRecord>& records,
                           const std::filesystem::path& folder) {
  std::vector<std::string> header = plan.keys;
  for (auto c : {"point"sv, "status"sv, "error"sv, "phi"sv, "mu0"sv, "lambda"sv})
    header.emplace_back(c);
  for (auto c : kSummaryBefore) header.emplace_back(c);
  header.emplace_back("phi_realized");
  for (auto c : kSummaryAfter) header.emplace_back(c);
  for (auto c :
       {"sample"sv, "start"sv, "dir"sv, "jam_cold_start"sv, "jam_cold_start_phi"sv,
        "jam_cold_start_phi_bulk"sv, "jam_phi_bulk_start"sv, "jam_cold_start_phi_bulk_start"sv})
    header.emplace_back(c);

  std::string out;
  for (std::size_t k = 0; k < header.size(); ++k) out += (k ? "," : "") + field(header[k]);
  out += "\n";
  for (const auto& p : plan.points) {
    const PointRecord& r = records[p.index];
    std::vector<std::string> row;
    for (const auto& key : plan.keys) {
      const auto* value = find_key(p.config.resolved, key);
      row.push_back(value ? field(value->is_string() ? plain_text(*value) : toml_value_text(*value))
                          : "");
    }
    row.push_back(fmt::format("{}", p.index));
    row.emplace_back(status_name(r.status));
    row.push_back(
        r.status == PointStatus::Failed || r.status == PointStatus::Skipped ? field(r.error) : "");
    row.push_back(fmt::format("{}", p.config.cell()->phi));
    row.push_back(fmt::format("{}", p.config.friction.mu0));
    row.push_back(fmt::format("{}", p.config.fluid.lambda));
    for (auto c : kSummaryBefore) row.push_back(summary_field(r, c));
    row.push_back(summary_field(r, "phi"));
    for (auto c : kSummaryAfter) row.push_back(summary_field(r, c));
    row.push_back(field(sample_label(plan, p)));
    row.push_back(p.continues_from ? field(plan.points[*p.continues_from].folder)
                  : p.refines      ? field(folder.empty() ? p.refines->ramp.back().generic_string()
                                                          : std::filesystem::proximate(
                                                                p.refines->ramp.back(),
                                                                std::filesystem::absolute(folder))
                                                                .generic_string())
                                   : "cold");
    row.push_back(field(p.folder));
    const bool confirmable = plan.settings.confirm_jams && is_continued(p) && jammed(r);
    row.push_back(!confirmable                          ? ""
                  : !r.cold_start.is_object()           ? "pending"
                  : r.cold_start.value("jammed", false) ? "jammed"
                                                        : "flowed");
    // The cold start's nominal phi and the bulk fraction it reached
    // (sweep.cold_start_phi; docs/sweeps.md "Ramps to the jam").
    for (auto c : {"phi_requested"sv, "phi_bulk"sv}) row.push_back(member_field(r.cold_start, c));
    // Where the jammed point and its cold start began (sweep.cold_start_phi = "bulk").
    for (auto c : {"target_phi_bulk"sv, "phi_bulk_start"sv})
      row.push_back(member_field(r.cold_start_choice, c));
    for (std::size_t k = 0; k < row.size(); ++k) out += (k ? "," : "") + row[k];
    out += "\n";
  }
  return out;
}

}  // namespace dilatant::sweep
