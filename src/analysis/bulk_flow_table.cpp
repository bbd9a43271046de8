#include "analysis/bulk_flow_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/delimited_text.hpp"
#include "dilatant/builtin_tables.hpp"
#include "io/input_error.hpp"

namespace dilatant::analysis {

namespace {

std::optional<BulkState> bulk_state_of(const std::string& text) {
  if (text == "cst") return BulkState::Cst;
  if (text == "dst") return BulkState::Dst;
  if (text == "jammed") return BulkState::Jammed;
  return std::nullopt;
}

// The dst_evidence column's text, the flow-curve analysis's word; empty is a
// row that is not dst, or a table written before the column (whose dst rows
// are jams).
DstEvidence dst_evidence_of(const NumericCsv& csv, std::size_t r, BulkState state,
                            const std::string& text) {
  if (text.empty()) return state == BulkState::Dst ? DstEvidence::Jammed : DstEvidence::None;
  if (state != BulkState::Dst)
    csv.fail(r, fmt::format("dst_evidence \"{}\" on a {} row: only a dst row has evidence", text,
                            bulk_state_name(state)));
  for (const DstEvidence e : {DstEvidence::Jammed, DstEvidence::RateFalls,
                              DstEvidence::RateNotIncreasing, DstEvidence::ExponentAboveCap})
    if (text == dst_evidence_name(e)) return e;
  csv.fail(r, fmt::format("dst_evidence \"{}\": must be jammed, rate_falls, rate_not_increasing "
                          "or n_above_cap",
                          text));
}

// A dst ramp without a jam flowed at every stress: it has no jam_lambda, and
// where its rate fell it says (rate_falls always does).
void check_flowing_dst_row(const NumericCsv& csv, std::size_t r, const BulkFlowState& s) {
  if (s.fall_lambda != 0.0 && !(s.fall_lambda > 0.0 && s.fall_lambda <= s.max_lambda))
    csv.fail(r, fmt::format("fall_lambda {}: the rate falls at a stress the ramp flowed at, "
                            "0 < fall_lambda <= max_lambda {}",
                            s.fall_lambda, s.max_lambda));
  if (s.fall_lambda != 0.0 && s.state != BulkState::Dst)
    csv.fail(r, fmt::format("fall_lambda {} on a {} row: a rate that falls is DST", s.fall_lambda,
                            bulk_state_name(s.state)));
  if (s.state != BulkState::Dst || s.dst_evidence == DstEvidence::Jammed) return;
  if (!(s.max_lambda > 0.0) || s.jam_lambda != 0.0 ||
      (s.dst_evidence == DstEvidence::RateFalls && s.fall_lambda == 0.0))
    csv.fail(r, fmt::format("dst by {} with max_lambda {}, jam_lambda {} and fall_lambda {}: needs "
                            "max_lambda > 0, no jam_lambda, and fall_lambda for rate_falls",
                            dst_evidence_name(s.dst_evidence), s.max_lambda, s.jam_lambda,
                            s.fall_lambda));
}

// The row's own consistency: a ramp that flowed says how far, one that jammed
// says where, and a cst ramp has no jam.
void check_bulk_row(const NumericCsv& csv, std::size_t r, const BulkFlowState& s) {
  if (!(s.mu0 >= 0.0) || !(s.phi_bulk > 0.0 && s.phi_bulk < 0.74))
    csv.fail(r, fmt::format("mu0 {}, phi_bulk {}: need mu0 >= 0 and phi_bulk in (0, 0.74)", s.mu0,
                            s.phi_bulk));
  check_flowing_dst_row(csv, r, s);
  if (s.state == BulkState::Dst && s.dst_evidence != DstEvidence::Jammed) return;
  const bool flowed = s.state != BulkState::Jammed, jammed = s.state != BulkState::Cst;
  if (flowed != (s.max_lambda > 0.0) || jammed != (s.jam_lambda > 0.0) || s.max_lambda < 0.0 ||
      s.jam_lambda < 0.0)
    csv.fail(r, fmt::format("regime {} with max_lambda {} and jam_lambda {}: a cst or dst ramp "
                            "needs max_lambda > 0, a dst or jammed one jam_lambda > 0, and the "
                            "others are empty",
                            bulk_state_name(s.state), s.max_lambda, s.jam_lambda));
  if (s.state == BulkState::Dst && !(s.jam_lambda > s.max_lambda))
    csv.fail(r, fmt::format("dst ramp jammed at lambda {}, not above its last flowing lambda {}",
                            s.jam_lambda, s.max_lambda));
  if (s.source.empty()) csv.fail(r, "no source: every row names the flow curves it was read from");
}

// Rows of one mu0 must keep the order the decision rule assumes: cst below
// dst below jammed, in phi. The later row of a contradicting pair is blamed.
void check_bulk_order(const NumericCsv& csv, const std::vector<BulkFlowState>& rows) {
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (std::size_t b = 0; b < rows.size(); ++b) {
      const BulkFlowState &lo = rows[a], &hi = rows[b];
      if (std::abs(lo.mu0 - hi.mu0) > kBulkMu0Tolerance ||
          static_cast<int>(lo.state) >= static_cast<int>(hi.state) || lo.phi_bulk < hi.phi_bulk)
        continue;
      const BulkFlowState &later = rows[std::max(a, b)], &earlier = rows[std::min(a, b)];
      csv.fail(std::max(a, b),
               fmt::format("mu0 {}: this {} ramp at phi_bulk {} contradicts the {} ramp at "
                           "phi_bulk {} on line {}: no ramp flows at or above a fraction where "
                           "another of its mu0 jams",
                           later.mu0, bulk_state_name(later.state), later.phi_bulk,
                           bulk_state_name(earlier.state), earlier.phi_bulk, earlier.line));
    }
}

std::string measured_state_text(const BulkFlowState& s) {
  const std::string what =
      s.state == BulkState::Cst ? fmt::format("CST to lambda {:g}", s.max_lambda)
      : s.state == BulkState::Dst && s.dst_evidence != DstEvidence::Jammed
          ? fmt::format("flowed to lambda {:g} without a jam, DST by {}{}", s.max_lambda,
                        dst_evidence_name(s.dst_evidence),
                        s.fall_lambda > 0.0
                            ? fmt::format(" (its rate fell at lambda {:g} as the stress rose)",
                                          s.fall_lambda)
                            : std::string())
      : s.state == BulkState::Dst
          ? fmt::format("flowed to lambda {:g}, jammed at {:g}", s.max_lambda, s.jam_lambda)
          : fmt::format("jammed at lambda {:g}", s.jam_lambda);
  return fmt::format("mu0 {:g}, phi_bulk {:.4f}, {} Lees-Edwards box: {} ({}{})", s.mu0, s.phi_bulk,
                     s.cell, what, s.source, s.sample.empty() ? "" : ", curve " + s.sample);
}

}  // namespace

std::string_view bulk_state_name(BulkState s) {
  switch (s) {
    case BulkState::Cst:
      return "cst";
    case BulkState::Dst:
      return "dst";
    case BulkState::Jammed:
      break;
  }
  return "jammed";
}

BulkFlowTable BulkFlowTable::parse(const NumericCsv& csv) {
  constexpr std::string_view needs =
      "mu0, phi_bulk, regime, max_lambda, jam_lambda, cell, source, sample";
  const std::size_t c_mu = csv.column("mu0", needs), c_phi = csv.column("phi_bulk", needs),
                    c_regime = csv.column("regime", needs), c_max = csv.column("max_lambda", needs),
                    c_jam = csv.column("jam_lambda", needs), c_cell = csv.column("cell", needs),
                    c_source = csv.column("source", needs), c_sample = csv.column("sample", needs);
  const auto c_evidence = csv.find_column("dst_evidence"), c_fall = csv.find_column("fall_lambda"),
             c_unconverged = csv.find_column("max_frac_unconverged");
  BulkFlowTable t;
  t.name_ = csv.source();
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const auto state = bulk_state_of(csv.text(r, c_regime));
    if (!state)
      csv.fail(r, fmt::format("regime \"{}\": must be cst, dst or jammed", csv.text(r, c_regime)));
    BulkFlowState s{csv.number(r, c_mu, "mu0"),
                    csv.number(r, c_phi, "phi_bulk"),
                    *state,
                    csv.number_or(r, c_max, "max_lambda", 0.0),
                    csv.number_or(r, c_jam, "jam_lambda", 0.0),
                    csv.text(r, c_cell),
                    csv.text(r, c_source),
                    csv.text(r, c_sample),
                    csv.line_of(r)};
    s.dst_evidence =
        dst_evidence_of(csv, r, s.state, c_evidence ? csv.text(r, *c_evidence) : std::string());
    if (c_fall) s.fall_lambda = csv.number_or(r, *c_fall, "fall_lambda", 0.0);
    if (c_unconverged) {
      s.max_frac_unconverged = csv.number_or(r, *c_unconverged, "max_frac_unconverged", 0.0);
      if (!(s.max_frac_unconverged >= 0.0 && s.max_frac_unconverged <= 1.0))
        csv.fail(r, fmt::format("max_frac_unconverged {}: a share of steps, in [0, 1]",
                                s.max_frac_unconverged));
    }
    check_bulk_row(csv, r, s);
    t.rows_.push_back(std::move(s));
  }
  if (t.rows_.empty()) throw InputError(csv.source() + ": the bulk flow table has no rows");
  check_bulk_order(csv, t.rows_);
  return t;
}

BulkFlowTable BulkFlowTable::read(const std::filesystem::path& file) {
  return parse(NumericCsv(read_text_lines(file), file.string()));
}

BulkFlowTable BulkFlowTable::builtin() {
  return parse(
      NumericCsv::from_text(kBulkFlowTableCsv, "data/jamming/bulk_flow_states.csv (built in)"));
}

BulkDecision decide_from_bulk(const BulkFlowTable& table, double mu0, double phi) {
  // The tolerance is inclusive for numbers written in decimal: 0.5805 is
  // within 0.0005 of 0.580 although the doubles' sum may round below it.
  constexpr double reach = kBulkPhiTolerance * (1.0 + 1e-9);
  BulkDecision d;
  // The deciding cst row: the one covering phi that went furthest in stress,
  // then the one nearest phi; the deciding dst row: of those within reach of
  // phi, the nearest, then the best converged; the loosest dst and jammed rows.
  const BulkFlowState *cst = nullptr, *densest_cst = nullptr, *dst = nullptr,
                      *loosest_dst = nullptr, *jam = nullptr;
  for (const auto& s : table.rows()) {
    if (std::abs(s.mu0 - mu0) > kBulkMu0Tolerance) continue;
    if (s.state == BulkState::Cst) {
      if (!densest_cst || s.phi_bulk > densest_cst->phi_bulk) densest_cst = &s;
      if (phi > s.phi_bulk + reach) continue;
      if (!cst || s.max_lambda > cst->max_lambda ||
          (s.max_lambda == cst->max_lambda &&
           std::abs(s.phi_bulk - phi) < std::abs(cst->phi_bulk - phi)))
        cst = &s;
    } else if (s.state == BulkState::Dst) {
      if (!loosest_dst || s.phi_bulk < loosest_dst->phi_bulk) loosest_dst = &s;
      const double off = std::abs(s.phi_bulk - phi);
      if (off > reach) continue;
      if (!dst || off < std::abs(dst->phi_bulk - phi) ||
          (off == std::abs(dst->phi_bulk - phi) &&
           s.max_frac_unconverged < dst->max_frac_unconverged))
        dst = &s;
    } else if (!jam || s.phi_bulk < jam->phi_bulk) {
      jam = &s;
    }
  }
  const auto decide = [&](FlowRegime r, const BulkFlowState& s) {
    d.regime = r;
    d.row = s;
    d.reason = measured_state_text(s);
    return d;
  };
  if (cst) return decide(FlowRegime::Cst, *cst);
  if (jam && phi >= jam->phi_bulk - reach) return decide(FlowRegime::NoFlow, *jam);
  if (dst) return decide(FlowRegime::Dst, *dst);
  if (!densest_cst && !loosest_dst && !jam)
    d.reason = fmt::format("no bulk flow curve at mu0 {:g} in {}", mu0, table.name());
  else if (densest_cst)
    d.reason = fmt::format(
        "the bulk flow curves at mu0 {:g} flow up to phi_bulk {:.4f} ({}); "
        "phi {:g} is above that and not decided by them",
        mu0, densest_cst->phi_bulk, table.name(), phi);
  else
    d.reason = fmt::format(
        "the bulk flow curves at mu0 {:g} start at phi_bulk {:.4f} ({}); phi "
        "{:g} is not within {:g} of a measured state",
        mu0, (loosest_dst ? loosest_dst : jam)->phi_bulk, table.name(), phi, kBulkPhiTolerance);
  return d;
}

}  // namespace dilatant::analysis
