// A refinement of another sweep's ramps (sweep.refines; sweep_plan.hpp): each
// point finds its ramp in the refined sweep (the one whose configuration is
// its own but for fluid.lambda) and starts from the final state of that ramp's
// point at the nearest lower lambda.
//
// Why the nearest lower lambda, and not the refinement's own previous point: a
// ramp's state at a stress is the history of the stresses below it, and the
// refined ramp has run them; starting each extra point from it keeps that
// history, makes the step into the point smaller than the ramp's own step
// (issue 34: stress points at most a factor 3 apart where a curve bends), and
// leaves the extra points independent of each other, so they run side by side.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "sweep/sweep_plan_detail.hpp"

namespace dilatant::sweep::detail {
namespace {

// The dotted keys at which two resolved configurations differ.
void differences(const toml::table& a, const toml::table& b, const std::string& prefix,
                 std::vector<std::string>& out) {
  for (const auto& [k, v] : a) {
    const std::string key = prefix + std::string(k.str());
    const toml::node* w = b.get(k.str());
    if (w == nullptr)
      out.push_back(key);
    else if (v.is_table() && w->is_table())
      differences(*v.as_table(), *w->as_table(), key + ".", out);
    else if (toml_value_text(v) != toml_value_text(*w))
      out.push_back(key);
  }
  for (const auto& [k, v] : b)
    if (a.get(k.str()) == nullptr) out.push_back(prefix + std::string(k.str()));
}

// The refined sweep's ramps: each its points' indices in order of lambda.
std::vector<std::vector<std::size_t>> ramps_of(const SweepPlan& refined) {
  std::vector<std::optional<std::size_t>> next(refined.points.size());
  for (const auto& p : refined.points)
    if (p.continues_from) next[*p.continues_from] = p.index;
  std::vector<std::vector<std::size_t>> ramps;
  for (const auto& p : refined.points) {
    if (p.continues_from) continue;
    ramps.emplace_back();
    for (std::optional<std::size_t> i = p.index; i; i = next[*i]) ramps.back().push_back(*i);
  }
  return ramps;
}

SweepPlan load_refined(const SweepPlan& plan) {
  const auto dir = plan.settings.refines;
  SweepPlan refined;
  try {
    refined = load_sweep(dir / "sweep.toml", {});
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("{}: sweep.refines = {}: {}", plan.source, dir.string(), e.what()));
  }
  if (!refined.settings.continuation || !refined.settings.refines.empty())
    throw InputError(fmt::format(
        "{}: sweep.refines = {}: not a ramp sweep ({}); refine a sweep with "
        "sweep.continuation = true",
        plan.source, dir.string(),
        refined.settings.continuation ? "it refines another sweep itself" : "no continuation"));
  return refined;
}

std::string point_name(const SweepPoint& p) {
  return fmt::format("point {} ({})", p.index, p.label);
}

}  // namespace

void link_refinement(SweepPlan& plan) {
  if (!plan.settings.continuation)
    throw InputError(fmt::format(
        "{}: sweep.refines needs sweep.continuation = true (its points continue a ramp)",
        plan.source));
  const SweepPlan refined = load_refined(plan);
  const auto ramps = ramps_of(refined);
  const auto dir = plan.settings.refines;
  for (auto& p : plan.points) {
    // The ramp whose cold start is this point's configuration at its lambda.
    const std::vector<std::size_t>* ramp = nullptr;
    std::vector<std::string> closest;
    for (const auto& r : ramps) {
      Config first = refined.points[r.front()].config;
      first.fluid.lambda = p.config.fluid.lambda;
      std::vector<std::string> differ;
      differences(p.config.resolved, to_toml(first), "", differ);
      if (differ.empty()) {
        ramp = &r;
        break;
      }
      if (closest.empty() || differ.size() < closest.size()) closest = std::move(differ);
    }
    if (ramp == nullptr)
      throw InputError(fmt::format(
          "{}: {} matches no ramp of {} (the closest differs in {}): a refinement's point is "
          "configured as its ramp but for fluid.lambda",
          plan.source, point_name(p), dir.string(), join(closest, ", ")));
    RampStart start;
    const double lambda = p.config.fluid.lambda;
    for (std::size_t i : *ramp) {
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
          plan.source, point_name(p), lambda, refined.points[ramp->front()].config.fluid.lambda));
    start.shown = std::filesystem::proximate(start.ramp.back()).string();
    p.refines = std::move(start);
    continue_point(plan, p);
  }
}

}  // namespace dilatant::sweep::detail
