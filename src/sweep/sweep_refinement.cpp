// A refinement of another sweep's ramps (sweep.refines; sweep_plan.hpp): each
// point finds its ramp in the refined sweep (the one whose configuration is
// its own but for fluid.lambda). The extra points between two of the ramp's
// points form a short ramp of their own: the lowest starts from the final
// state of the ramp's point below, each next one from the previous extra
// point's.
//
// Why so: a ramp's state at a stress is the history of the stresses below it,
// and the refined ramp has run them; starting each segment from it keeps that
// history, and chaining the segment's points keeps every stress step as small
// as the spacing of the extra points (issue 34: stress points at most a factor
// 3 apart where a curve bends; lambda 10^(1/6) apart is a stress step of 2.15).
// Segments are independent of each other and run side by side.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/config_compare.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"
#include "sweep/sweep_plan_detail.hpp"

namespace dilatant::sweep::detail {
namespace {

using namespace std::string_view_literals;

SweepPlan load_refined(const SweepPlan& plan) {
  const auto dir = plan.settings.refines;
  const auto fail = [&](const std::string& why) {
    return InputError(fmt::format("{}: sweep.refines = {}: {}", plan.source, dir.string(), why));
  };
  const auto file = dir / "sweep.toml";
  toml::table head;
  try {
    head = toml::parse(read_input_file(file, "refined sweep"), file.string());
  } catch (const toml::parse_error& e) {
    throw fail(fmt::format("{}: invalid TOML: {}", file.string(), e.description()));
  } catch (const InputError& e) {
    throw fail(e.what());
  }
  // Checked before the file is read as a sweep: a refinement of a refinement
  // (or of itself) would otherwise load its own refined sweep, and so on.
  if (head["sweep"]["refines"])
    throw fail("it refines another sweep itself; refine the ramp sweep it refines");
  if (!head["sweep"]["continuation"].value_or(false))
    throw fail("not a ramp sweep (no sweep.continuation); refine a sweep with continuation = true");
  try {
    return load_sweep(file, {});
  } catch (const InputError& e) {
    throw fail(e.what());
  }
}

std::string point_name(const SweepPoint& p) {
  return fmt::format("point {} ({})", p.index, p.label);
}

// The ramp whose first (cold) point is `p`'s configuration but for lambda, or
// an InputError naming how the closest ramp (most swept keys equal) differs.
const std::vector<std::size_t>& ramp_of(const SweepPlan& plan, const SweepPoint& p,
                                        const SweepPlan& refined,
                                        const std::vector<std::vector<std::size_t>>& ramps) {
  constexpr std::string_view kLambda[] = {"fluid.lambda"sv};
  const std::vector<std::size_t>* closest = nullptr;
  int closest_equal = -1;
  for (const auto& r : ramps) {
    const SweepPoint& first = refined.points[r.front()];
    if (!config_difference(resolved_toml(first.config), p.config, "here", kLambda)) return r;
    int equal = 0;
    for (std::size_t k = 0; k < refined.keys.size(); ++k) {
      const auto* mine = find_key(p.config.resolved, refined.keys[k]);
      equal += mine != nullptr && toml_value_text(*mine) == first.values[k];
    }
    if (equal > closest_equal) closest = &r, closest_equal = equal;
  }
  if (closest == nullptr)
    throw InputError(fmt::format("{}: sweep.refines = {}: it has no points", plan.source,
                                 plan.settings.refines.string()));
  const SweepPoint& first = refined.points[closest->front()];
  throw InputError(fmt::format(
      "{}: {} matches no ramp of {}; the closest ({}) differs: {} (a refinement's point is "
      "configured as its ramp but for fluid.lambda)",
      plan.source, point_name(p), plan.settings.refines.string(), first.label,
      *config_difference(resolved_toml(first.config), p.config, "here", kLambda)));
}

}  // namespace

void link_refinement(SweepPlan& plan) {
  const SweepPlan refined = load_refined(plan);
  const auto ramps = continuation_chains(refined);  // in order of lambda
  const auto dir = plan.settings.refines;
  // The extra points of each segment (ramp, index of the ramp's point below).
  std::map<std::pair<const void*, std::size_t>, std::vector<std::size_t>> segments;
  std::vector<RampStart> starts(plan.points.size());
  for (auto& p : plan.points) {
    const std::vector<std::size_t>& ramp = ramp_of(plan, p, refined, ramps);
    const double lambda = p.config.fluid.lambda;
    RampStart& start = starts[p.index];
    for (std::size_t i : ramp) {
      const SweepPoint& q = refined.points[i];
      if (q.config.fluid.lambda == lambda)
        throw InputError(
            fmt::format("{}: {}: lambda {} is a point of the refined ramp already ({})",
                        plan.source, point_name(p), lambda, (dir / q.folder).string()));
      if (q.config.fluid.lambda < lambda) start.ramp.push_back(dir / q.folder);
    }
    if (start.ramp.empty())
      throw InputError(fmt::format(
          "{}: {}: lambda {} is below its ramp's first point (lambda {}): no state to start from",
          plan.source, point_name(p), lambda, refined.points[ramp.front()].config.fluid.lambda));
    segments[{&ramp, start.ramp.size()}].push_back(p.index);
  }
  for (auto& [segment, points] : segments) {
    std::sort(points.begin(), points.end(), [&](std::size_t a, std::size_t b) {
      return plan.points[a].config.fluid.lambda < plan.points[b].config.fluid.lambda;
    });
    plan.points[points.front()].refines = std::move(starts[points.front()]);
    for (std::size_t k = 1; k < points.size(); ++k)
      plan.points[points[k]].continues_from = points[k - 1];
    for (std::size_t i : points) continue_point(plan, plan.points[i]);
  }
}

}  // namespace dilatant::sweep::detail
