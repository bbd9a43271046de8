// What the expanded points of a sweep are called and how they follow one
// another: labels and folders from the swept keys, continuation chains, and the
// plan written back as a sweep file (sweep_plan.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "io/config_compare.hpp"
#include "io/input_error.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_plan_detail.hpp"

namespace dilatant::sweep {
namespace {

using detail::join;

constexpr std::string_view kLambdaKey = "fluid.lambda";
constexpr std::size_t kMaxLabelLength = 80;

std::string short_name(const std::string& key, const std::vector<std::string>& keys) {
  const std::string last = key.substr(key.rfind('.') + 1);
  const auto same = std::count_if(keys.begin(), keys.end(), [&](const std::string& k) {
    return k.substr(k.rfind('.') + 1) == last;
  });
  return same > 1 ? key : last;
}

std::string label_of(const SweepPlan& plan, const Config& config) {
  std::vector<std::string> parts;
  for (const auto& key : plan.keys) {
    const auto* value = find_key(config.resolved, key);
    parts.push_back(short_name(key, plan.keys) + "=" + (value ? plain_text(*value) : "?"));
  }
  std::string label = join(parts, "_");
  for (char& c : label) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '=' || c == '+' || c == '-';
    if (!safe) c = '-';
  }
  if (label.size() > kMaxLabelLength) label.resize(kMaxLabelLength);
  return label.empty() ? "point" : label;
}

}  // namespace

namespace detail {

std::string join(const std::vector<std::string>& parts, std::string_view separator) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : std::string(separator)) + p;
  return out;
}

void name_points(SweepPlan& plan) {
  const std::size_t width =
      std::max<std::size_t>(3, fmt::format("{}", plan.points.size() - 1).size());
  for (auto& p : plan.points) {
    for (const auto& key : plan.keys) {
      const auto* value = find_key(p.config.resolved, key);
      p.values.push_back(value ? toml_value_text(*value) : "");
    }
    p.label = label_of(plan, p.config);
    p.folder = fmt::format("points/{:0{}}-{}", p.index, width, p.label);
    p.config.source =
        fmt::format("{}, point {} of {} ({})", plan.source, p.index, plan.points.size(), p.folder);
  }
}

void link_continuations(SweepPlan& plan) {
  const auto lambda_at = std::find(plan.keys.begin(), plan.keys.end(), kLambdaKey);
  if (lambda_at == plan.keys.end())
    throw InputError(fmt::format(
        "{}: sweep.continuation = true, but fluid.lambda is not swept: a point continues "
        "from the neighbouring lambda of its flow curve",
        plan.source));
  const auto lambda_column = static_cast<std::size_t>(lambda_at - plan.keys.begin());
  std::map<std::vector<std::string>, std::vector<std::size_t>> chains;
  for (const auto& p : plan.points) {
    auto key = p.values;
    key.erase(key.begin() + static_cast<long>(lambda_column));
    chains[key].push_back(p.index);
  }
  for (auto& [key, chain] : chains) {
    std::sort(chain.begin(), chain.end(), [&](std::size_t a, std::size_t b) {
      return plan.points[a].config.fluid.lambda < plan.points[b].config.fluid.lambda;
    });
    for (std::size_t k = 1; k < chain.size(); ++k) {
      SweepPoint& p = plan.points[chain[k]];
      p.continues_from = chain[k - 1];
      continue_point(plan, p);
    }
  }
}

void continue_point(const SweepPlan& plan, SweepPoint& p) {
  const SweepSettings& s = plan.settings;
  p.cold_start = p.config;
  RunConfig& run = p.config.run;
  if (s.continuation_strain) run.strain = *s.continuation_strain;
  if (s.continuation_transient_strain) run.transient_strain = *s.continuation_transient_strain;
  if (!(run.transient_strain < run.strain))
    throw InputError(
        fmt::format("{}: a continued point would run to strain {} with a transient of {}: set "
                    "sweep.continuation_transient_strain below sweep.continuation_strain (or "
                    "run.strain)",
                    plan.source, run.strain, run.transient_strain));
  p.config.resolved = to_toml(p.config);
}

// A cap below a point's own strain would cut no run short and extend none: a
// mistake, not a setting.
void check_extension_cap(const SweepPlan& plan) {
  if (const auto cap = plan.settings.extend_unsteady_to)
    for (const SweepPoint& p : plan.points)
      if (*cap < p.config.run.strain)
        throw InputError(fmt::format(
            "{}: sweep.extend_unsteady_to = {} is below the run.strain of point {} ({}): it "
            "is the largest strain a point not steady runs on to",
            plan.source, *cap, p.folder, p.config.run.strain));
}

}  // namespace detail

std::vector<std::vector<std::size_t>> continuation_chains(const SweepPlan& plan) {
  std::vector<std::optional<std::size_t>> next(plan.points.size());
  for (const auto& p : plan.points)
    if (p.continues_from) next[*p.continues_from] = p.index;
  std::vector<std::vector<std::size_t>> chains;
  for (const auto& p : plan.points) {
    if (p.continues_from) continue;  // in its chain
    chains.emplace_back();
    for (std::optional<std::size_t> i = p.index; i; i = next[*i]) chains.back().push_back(*i);
  }
  return chains;
}

const toml::node* find_key(const toml::table& resolved, std::string_view key) {
  return find_dotted_key(resolved, key);
}

std::string plain_text(const toml::node& value) {
  if (const auto* s = value.as_string()) return s->get();
  if (const auto* d = value.as_floating_point()) return fmt::format("{}", d->get());
  if (const auto* a = value.as_array()) {
    std::vector<std::string> parts;
    for (const auto& e : *a) parts.push_back(plain_text(e));
    return join(parts, "x");
  }
  return toml_value_text(value);  // integers, booleans
}

std::string resolved_sweep_toml(const SweepPlan& plan) {
  std::string out = fmt::format(
      "# dilatant: the resolved sweep of {} ({} points; swept: {}).\n"
      "# Every point is listed: `dilatant sweep` of this file into the same --out\n"
      "# is the same sweep and resumes it. Keys: dilatant run --help, docs/sweeps.md.\n",
      plan.source, plan.points.size(), plan.keys.empty() ? "nothing" : join(plan.keys, ", "));
  const SweepSettings& s = plan.settings;
  out += fmt::format("\n[sweep]\njobs = {}\ncontinuation = {}\n", s.jobs, s.continuation);
  if (s.continuation)
    out += fmt::format("stop_at_jam = {}\nconfirm_jams = {}\ncold_start_phi = \"{}\"\n",
                       s.stop_at_jam, s.confirm_jams,
                       s.cold_start_phi == SweepSettings::ColdStartPhi::Matched ? "matched"
                       : s.cold_start_phi == SweepSettings::ColdStartPhi::Bulk  ? "bulk"
                                                                                : "nominal");
  if (!s.refines.empty())
    out += fmt::format("refines = {}\n",
                       toml_value_text(toml::value<std::string>(s.refines.string())));
  if (s.extend_unsteady_to)
    out += fmt::format("extend_unsteady_to = {}\n",
                       toml_value_text(toml::value<double>(*s.extend_unsteady_to)));
  if (s.continuation_strain)
    out += fmt::format("continuation_strain = {}\n",
                       toml_value_text(toml::value<double>(*s.continuation_strain)));
  if (s.continuation_transient_strain)
    out += fmt::format("continuation_transient_strain = {}\n",
                       toml_value_text(toml::value<double>(*s.continuation_transient_strain)));
  // The shared keys: those of a point as a cold start (continued points may
  // have their own run.strain, which the [sweep] settings give them again).
  if (!plan.points.empty()) {
    const SweepPoint& first = plan.points.front();
    std::istringstream lines(resolved_toml(first.cold_start.value_or(first.config)));
    for (std::string line; std::getline(lines, line);)
      if (line.rfind('#', 0) != 0) out += line + "\n";
  }
  for (const auto& p : plan.points) {
    out += fmt::format("\n[[points]]  # {}\n", p.folder);
    for (std::size_t k = 0; k < plan.keys.size(); ++k)
      out += fmt::format("{} = {}\n", plan.keys[k], p.values[k]);
  }
  return out;
}

}  // namespace dilatant::sweep
