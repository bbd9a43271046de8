#include "sweep/cold_start_choice.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "drivers/starting_fraction.hpp"
#include "io/text.hpp"

namespace dilatant::sweep {
namespace {

double summary_phi_bulk(const PointRecord& r) {
  const auto it = r.summary.is_object() ? r.summary.find("phi_bulk") : r.summary.end();
  return it != r.summary.end() && it->is_number() ? it->get<double>()
                                                  : std::numeric_limits<double>::quiet_NaN();
}

void set_phi(Config& config, double phi) {
  config.cell()->phi = phi;
  config.resolved = to_toml(config);
}

// Matched: a wall cell's bulk fraction is not its nominal phi (the layers at
// the walls are looser), and a ramp compacts (or dilates) its bulk as it goes,
// so a cold start at the ramp's nominal phi starts from another packing
// fraction than the state the jammed point started from (0.010-0.015 denser
// on the paper's DST map). The ramp's first point is a cold start at the
// nominal phi: its phi_bulk measured the offset. Shift the nominal phi by the
// ramp's change of the bulk up to the jam, from the first point to the one the
// jammed point continued from,
//     phi_cold = phi + phi_bulk(previous point) - phi_bulk(first point),
// so that the cold start begins at the bulk fraction the stress step met, as
// far as the offset does not change over that shift. Not the jammed point's
// own phi_bulk: a jam dilates the packing it stops (by 0.02 in the small cell
// of tests/sweep/ramp_jam_test.cpp), and so does its cold start's. phi_bulk
// is a time average, not the final state; "bulk" measures the final state.
// In a Lees–Edwards box phi_bulk is the box's at every point: no shift.
// In a refinement (sweep.refines) the ramp's first point is the refined
// ramp's cold start, and a segment's lowest point started from the refined
// ramp's point below it: their summaries are read from those folders.
void match_time_averaged_bulk(const SweepPlan& plan, std::size_t i,
                              const std::vector<PointRecord>& records, Config& config) {
  const auto phi_bulk_in = [](const std::filesystem::path& folder) {
    PointRecord r;
    r.summary = nlohmann::json::parse(
        read_input_file(folder / "summary.json", "refined ramp's summary"), nullptr, false);
    return summary_phi_bulk(r);
  };
  const SweepPoint& p = plan.points[i];
  std::size_t head = i;
  while (plan.points[head].continues_from) head = *plan.points[head].continues_from;
  const RampStart* refined = plan.points[head].refines ? &*plan.points[head].refines : nullptr;
  const double first =
      refined ? phi_bulk_in(refined->ramp.front()) : summary_phi_bulk(records[head]);
  const double previous = p.continues_from ? summary_phi_bulk(records[*p.continues_from])
                                           : phi_bulk_in(p.refines->ramp.back());
  const double shift = previous - first;
  if (std::isfinite(shift) && shift != 0.0) set_phi(config, config.cell()->phi + shift);
}

// The folder of the run whose final state continued point i started from.
std::filesystem::path start_folder(const SweepPlan& plan, std::size_t i,
                                   const std::filesystem::path& out) {
  const SweepPoint& p = plan.points[i];
  return p.refines ? p.refines->ramp.back() : out / plan.points[*p.continues_from].folder;
}

nlohmann::json bulk_choice(const SweepPlan& plan, std::size_t i, const Config& config,
                           const std::filesystem::path& out, const std::atomic<bool>* stop) {
  const auto before = start_folder(plan, i, out);
  const auto checkpoint = before / "checkpoint.bin";
  const double target = checkpoint_bulk_fraction(checkpoint);
  const StartingFractionMatch m =
      match_starting_bulk(config, target, kBulkTolerance, kBulkMaxPackings, stop);
  if (!std::isfinite(m.phi_bulk_start))
    throw std::runtime_error(fmt::format(
        "none of the {} packings tried for the cold start (nominal phi from {:.4f}) could be "
        "built",
        m.tried.size(), config.cell()->phi));
  nlohmann::json j;
  j["rule"] = "bulk";
  j["target_phi_bulk"] = target;
  j["target_from"] = std::filesystem::proximate(checkpoint, out).generic_string();
  j["tolerance"] = kBulkTolerance;
  j["phi"] = m.phi;
  j["phi_bulk_start"] = m.phi_bulk_start;
  j["within_tolerance"] = m.within_tolerance;
  j["tried"] = nlohmann::json::array();
  for (const auto& [phi, bulk] : m.tried) j["tried"].push_back({{"phi", phi}, {"phi_bulk", bulk}});
  return j;
}

}  // namespace

ColdStartChoice choose_cold_start(const SweepPlan& plan, std::size_t jammed,
                                  const std::vector<PointRecord>& records,
                                  const std::filesystem::path& out, bool search,
                                  const std::atomic<bool>* stop) {
  const SweepPoint& p = plan.points[jammed];
  ColdStartChoice c{p.cold_start.value_or(p.config), nullptr};
  if (!is_continued(p) || c.config.cell() == nullptr) return c;
  switch (plan.settings.cold_start_phi) {
    case SweepSettings::ColdStartPhi::Nominal:
      return c;
    case SweepSettings::ColdStartPhi::Matched:
      match_time_averaged_bulk(plan, jammed, records, c.config);
      return c;
    case SweepSettings::ColdStartPhi::Bulk:
      break;
  }
  const auto file = out / p.folder / "cold-start" / kPhiChoiceFile;
  if (std::filesystem::is_regular_file(file)) {
    try {
      c.record = nlohmann::json::parse(read_input_file(file, "cold start's phi choice"));
      if (!c.record.contains("phi") || !c.record["phi"].is_number()) c.record = nullptr;
    } catch (const std::exception&) {
      c.record = nullptr;  // unreadable: chosen again
    }
  }
  if (c.record.is_null()) {
    if (!search) {
      c.unchosen = true;
      return c;
    }
    c.record = bulk_choice(plan, jammed, c.config, out, stop);
    c.fresh = true;
  }
  set_phi(c.config, c.record["phi"].get<double>());
  return c;
}

}  // namespace dilatant::sweep
