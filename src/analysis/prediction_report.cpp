#include "analysis/prediction_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "dilatant/version.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {

namespace {

nlohmann::json onset_json(const OnsetPrediction& o, double s_c) {
  if (!o.available || o.too_far) return nullptr;
  nlohmann::json curves = nlohmann::json::array();
  for (const auto& m : o.measured)
    curves.push_back({{"mu0", m.mu0},
                      {"phi_bulk", m.phi_bulk},
                      {"s_c", m.s_c},
                      {"seed", m.seed},
                      {"onset_rate", m.onset_rate},
                      {"inertial_number", m.inertial_number},
                      {"model", m.model},
                      {"source", m.source}});
  return {{"rate", o.rate},
          {"rate_range", {o.rate_low, o.rate_high}},
          {"rate_unit", "eta_f/(rho_p R^2)"},
          {"criterion", "frac_bl rises above its minimum (contacts leave the HD branch)"},
          {"scale_I2_over_s_c", o.scale},
          {"prefactor", o.prefactor},
          {"inertial_number", o.inertial_number},
          {"s_c", s_c},
          {"measured_at", std::move(curves)}};
}

}  // namespace

std::string onset_withheld(const OnsetPrediction& o, double phi) {
  return fmt::format(
      "the onset nearest in mu0 was measured at phi_bulk {:.3f} (mu0 {}), more than {} from phi "
      "{}; how the onset moves with phi is not measured, so none is given",
      o.phi_bulk, o.mu0, kOnsetPhiReach, phi);
}

void check_prediction_input(double mu0, double phi, double s_c, const PredictArgumentNames& names) {
  if (!(s_c > 0.0) || !std::isfinite(s_c))
    throw InputError(fmt::format("{} {}: must be a finite number > 0", names.s_c, s_c));
  if (!(mu0 >= 0.0) || !std::isfinite(mu0))
    throw InputError(fmt::format("{} {}: must be a finite number >= 0", names.mu0, mu0));
  if (!(phi > 0.0 && phi < 0.74))
    throw InputError(fmt::format("{} {}: must be in (0, 0.74)", names.phi, phi));
}

PredictionReport predict(const JammingTable& table, const BulkFlowTable* bulk, double mu0,
                         double phi, double s_c, const PredictArgumentNames& names) {
  check_prediction_input(mu0, phi, s_c, names);
  PredictionReport r;
  r.mu0 = mu0;
  r.phi = phi;
  r.s_c = s_c;
  r.regime = predict_regime(table, mu0, phi);
  if (bulk) {
    r.bulk = decide_from_bulk(*bulk, mu0, phi);
    r.bulk_table = bulk->name();
  }
  // No flow, no onset: the scale is given for the flowing regimes only.
  if (r.answer() != FlowRegime::NoFlow)
    r.onset = predict_onset(OnsetTable::builtin(), mu0, phi, s_c);
  r.mu0_table_max = table.points().back().mu0;
  return r;
}

std::string_view regime_source_name(RegimeSource s) {
  return s == RegimeSource::BulkFlowCurves ? "bulk flow curves" : "sediment table";
}

std::string source_detail(const PredictionReport& r, const std::string& table_name) {
  if (r.source() == RegimeSource::BulkFlowCurves)
    return fmt::format("bulk flow curves ({}, line {}: {})", r.bulk_table, r.bulk.row.line,
                       r.bulk.reason);
  return fmt::format(
      "sediment table ({}){}",
      table_name == "built-in" ? "data/jamming/phi_max_bl.csv (built in)" : table_name,
      r.bulk_table.empty() ? std::string("; no bulk table used")
                           : "; bulk flow curves: " + r.bulk.reason);
}

nlohmann::json prediction_json(const PredictionReport& r, const std::string& table_name) {
  const Prediction& p = r.regime;
  const bool bulk = r.source() == RegimeSource::BulkFlowCurves;
  const auto margin = [](double m) {
    return std::isfinite(m) ? nlohmann::json(m) : nlohmann::json(nullptr);
  };
  nlohmann::json j;
  // The other source: "wyart-cates fit" (wyart_cates_prediction.hpp).
  j["source"] = regime_source_name(r.source());
  j["source_detail"] = source_detail(r, table_name);
  j["mu0"] = r.mu0;
  j["phi"] = r.phi;
  j["regime"] = flow_regime_name(r.answer());
  // The sediment table's fractions, whichever source answered.
  j["phi_max_bl"] = p.phi_max_bl.value;
  j["phi_max_bl_err"] = p.phi_max_bl.error;
  j["phi_rcp"] = p.phi_rcp.value;
  j["phi_rcp_err"] = p.phi_rcp.error;
  // The answer's distance to the sediment's boundaries: none when the bulk
  // answered (a measured state has no sigma of the sediment's).
  j["margin_sigma"] = bulk ? nlohmann::json(nullptr) : margin(p.margin_sigma);
  j["uncertain"] = !bulk && p.uncertain;
  j["sediment"] = {{"regime", flow_regime_name(p.regime)},
                   {"margin_sigma", margin(p.margin_sigma)},
                   {"uncertain", p.uncertain}};
  if (bulk) {
    const BulkFlowState& s = r.bulk.row;
    j["bulk"] = {{"mu0", s.mu0},
                 {"phi_bulk", s.phi_bulk},
                 {"state", bulk_state_name(s.state)},
                 {"max_lambda", s.max_lambda > 0.0 ? nlohmann::json(s.max_lambda) : nullptr},
                 {"jam_lambda", s.jam_lambda > 0.0 ? nlohmann::json(s.jam_lambda) : nullptr},
                 {"dst_evidence", s.dst_evidence == DstEvidence::None
                                      ? nlohmann::json(nullptr)
                                      : nlohmann::json(dst_evidence_name(s.dst_evidence))},
                 {"fall_lambda", s.fall_lambda > 0.0 ? nlohmann::json(s.fall_lambda) : nullptr},
                 {"cell", s.cell},
                 {"source", s.source},
                 {"sample", s.sample},
                 {"line", s.line}};
  } else {
    j["bulk"] = nullptr;
  }
  j["bulk_reason"] = r.bulk_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.bulk.reason);
  j["mu0_beyond_table"] = r.mu0_beyond_table();
  j["onset"] = onset_json(r.onset, r.s_c);
  if (r.onset.available && r.onset.too_far) j["onset_withheld"] = onset_withheld(r.onset, r.phi);
  j["table"] = table_name;
  j["bulk_table"] = r.bulk_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.bulk_table);
  j["version"] = kVersion;
  return j;
}

}  // namespace dilatant::analysis
