#include "analysis/onset_table.hpp"

#include <fmt/format.h>

#include <cmath>

#include "dilatant/builtin_tables.hpp"

namespace dilatant::analysis {

OnsetTable OnsetTable::parse(const NumericCsv& csv) {
  constexpr std::string_view needs =
      "mu0, phi_bulk, s_c, onset_rate, inertial_number, model, source";
  const std::size_t c_mu = csv.column("mu0", needs), c_phi = csv.column("phi_bulk", needs),
                    c_sc = csv.column("s_c", needs), c_rate = csv.column("onset_rate", needs),
                    c_i = csv.column("inertial_number", needs),
                    c_model = csv.column("model", needs), c_source = csv.column("source", needs);
  OnsetTable t;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    MeasuredOnset o{csv.number(r, c_mu, "mu0"),
                    csv.number(r, c_phi, "phi_bulk"),
                    csv.number(r, c_sc, "s_c"),
                    csv.number(r, c_rate, "onset_rate"),
                    csv.number(r, c_i, "inertial_number"),
                    csv.text(r, c_model),
                    csv.text(r, c_source)};
    if (o.mu0 < 0.0 || !(o.phi_bulk > 0.0 && o.phi_bulk < 0.74) || !(o.s_c > 0.0) ||
        !(o.onset_rate > 0.0) || !(o.inertial_number > 0.0))
      csv.fail(r, fmt::format("mu0 {}, phi_bulk {}, s_c {}, onset_rate {}, inertial_number {}: "
                              "need mu0 >= 0, phi_bulk in (0, 0.74) and the others > 0",
                              o.mu0, o.phi_bulk, o.s_c, o.onset_rate, o.inertial_number));
    t.onsets_.push_back(std::move(o));
  }
  return t;
}

OnsetTable OnsetTable::builtin() {
  return parse(NumericCsv::from_text(kOnsetTableCsv, "data/jamming/onsets.csv (built in)"));
}

OnsetPrediction predict_onset(const OnsetTable& table, double mu0, double phi, double s_c) {
  OnsetPrediction out;
  const MeasuredOnset* best = nullptr;
  for (const auto& o : table.onsets()) {
    if (best == nullptr) {
      best = &o;
      continue;
    }
    const double d = std::abs(o.mu0 - mu0), d_best = std::abs(best->mu0 - mu0);
    if (d < d_best || (d == d_best && std::abs(o.phi_bulk - phi) < std::abs(best->phi_bulk - phi)))
      best = &o;
  }
  if (best == nullptr) return out;
  out.available = true;
  out.too_far = std::abs(best->phi_bulk - phi) > kOnsetPhiReach;
  out.measured = *best;
  out.prefactor = best->onset_rate / onset_rate_scale(best->inertial_number, best->s_c);
  out.scale = onset_rate_scale(best->inertial_number, s_c);
  out.rate = out.prefactor * out.scale;
  return out;
}

}  // namespace dilatant::analysis
