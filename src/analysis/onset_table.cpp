#include "analysis/onset_table.hpp"

#include <fmt/format.h>

#include <algorithm>
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
  const auto c_seed = csv.find_column("seed");
  OnsetTable t;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    MeasuredOnset o{csv.number(r, c_mu, "mu0"),
                    csv.number(r, c_phi, "phi_bulk"),
                    csv.number(r, c_sc, "s_c"),
                    csv.number(r, c_rate, "onset_rate"),
                    csv.number(r, c_i, "inertial_number"),
                    0,
                    csv.text(r, c_model),
                    csv.text(r, c_source)};
    if (o.mu0 < 0.0 || !(o.phi_bulk > 0.0 && o.phi_bulk < 0.74) || !(o.s_c > 0.0) ||
        !(o.onset_rate > 0.0) || !(o.inertial_number > 0.0))
      csv.fail(r, fmt::format("mu0 {}, phi_bulk {}, s_c {}, onset_rate {}, inertial_number {}: "
                              "need mu0 >= 0, phi_bulk in (0, 0.74) and the others > 0",
                              o.mu0, o.phi_bulk, o.s_c, o.onset_rate, o.inertial_number));
    if (c_seed) {  // a whole number >= 0 (0: not given)
      const double seed = csv.number(r, *c_seed, "seed");
      if (!(seed >= 0.0 && seed <= 1e9 && seed == std::floor(seed)))
        csv.fail(r, fmt::format("seed {}: need a whole number >= 0", seed));
      o.seed = static_cast<int>(seed);
    }
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
    const double d = std::abs(o.mu0 - mu0), d_best = best ? std::abs(best->mu0 - mu0) : 0.0;
    if (best == nullptr || d < d_best ||
        (d == d_best && std::abs(o.phi_bulk - phi) < std::abs(best->phi_bulk - phi)))
      best = &o;
  }
  if (best == nullptr) return out;
  // Every seed of that state (same mu0 and model, phi_bulk within
  // kOnsetSameState); C and I_c are averaged in log, so the rate is the
  // geometric mean of the curves' own C I_c^2/s_c.
  double log_c = 0.0, log_i = 0.0, phi_sum = 0.0;
  out.rate_low = HUGE_VAL;
  out.rate_high = 0.0;
  for (const auto& o : table.onsets()) {
    if (o.mu0 != best->mu0 || o.model != best->model ||
        std::abs(o.phi_bulk - best->phi_bulk) > kOnsetSameState)
      continue;
    const double c = o.onset_rate / onset_rate_scale(o.inertial_number, o.s_c);
    const double rate = c * onset_rate_scale(o.inertial_number, s_c);
    log_c += std::log(c);
    log_i += std::log(o.inertial_number);
    phi_sum += o.phi_bulk;
    out.rate_low = std::min(out.rate_low, rate);
    out.rate_high = std::max(out.rate_high, rate);
    out.measured.push_back(o);
  }
  const double n = static_cast<double>(out.measured.size());
  out.available = true;
  out.mu0 = best->mu0;
  out.phi_bulk = phi_sum / n;
  out.too_far = std::abs(out.phi_bulk - phi) > kOnsetPhiReach;
  out.prefactor = std::exp(log_c / n);
  out.inertial_number = std::exp(log_i / n);
  out.scale = onset_rate_scale(out.inertial_number, s_c);
  out.rate = out.prefactor * out.scale;
  return out;
}

}  // namespace dilatant::analysis
