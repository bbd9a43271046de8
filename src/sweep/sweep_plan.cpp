// From a sweep file to its points: lists and [[points]] tables expanded, every
// point validated as a run configuration (sweep_plan.hpp).
//
// toml++ keeps a node's source line when the node is moved but not when it is
// copied, and the messages of the config reader name lines. So the file is
// parsed afresh for each point and that point's values are moved into place;
// every value then still carries the line it was written on.
#include "sweep/sweep_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "io/input_error.hpp"
#include "io/text.hpp"
#include "sweep/sweep_plan_detail.hpp"

namespace dilatant::sweep {
namespace {

using namespace std::string_view_literals;

constexpr std::string_view kSweepTable = "sweep";
constexpr std::string_view kPointsTable = "points";
constexpr std::array kSettingsKeys = {"jobs"sv,
                                      "continuation"sv,
                                      "continuation_strain"sv,
                                      "continuation_transient_strain"sv,
                                      "stop_at_jam"sv,
                                      "confirm_jams"sv,
                                      "cold_start_phi"sv,
                                      "refines"sv,
                                      "extend_unsteady_to"sv};
// Keys whose single value is an array: swept only when given a list of arrays.
constexpr std::array kArrayKeys = {"cell.size"sv, "scene.gravity"sv, "scene.box"sv,
                                   "scene.periodic"sv, "scene.planes"sv};
// More points than this is a typo in a list, not a sweep.
constexpr std::size_t kMaxPoints = 100000;

using detail::join;

bool from_file(const toml::node& n, const std::string& source) {
  const auto& path = n.source().path;
  return n.source().begin.line > 0 && path && *path == source;
}

// "sweep.toml:7: friction.mu0" for a value of the file, "--set friction.mu0" else.
std::string where(const std::string& source, const toml::node& n, std::string_view key) {
  if (!from_file(n, source)) return fmt::format("--set {}", key);
  return fmt::format("{}:{}: {}", source, n.source().begin.line, key);
}

toml::table parse_text(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, std::string(source));
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: invalid TOML: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

// Moves `value` (a node of any type) into table[key], keeping its source line.
void move_into(toml::table& table, std::string_view key, toml::node& value) {
  value.visit([&](auto& v) {
    auto moved = std::move(v);
    table.insert_or_assign(key, std::move(moved));
  });
}

struct Overrides {
  std::vector<std::string> config;  // passed on to the config reader
  std::vector<std::string> config_keys;
  std::vector<std::pair<std::string, std::string>> settings;  // [sweep] key, value text
};

Overrides split_overrides(const std::vector<std::string>& overrides) {
  Overrides o;
  for (const auto& text : overrides) {
    const auto eq = text.find('=');
    const std::string key(trim(std::string_view(text).substr(0, std::min(eq, text.size()))));
    if (eq != std::string::npos && key.rfind("sweep.", 0) == 0) {
      o.settings.emplace_back(key.substr(6), trim(std::string_view(text).substr(eq + 1)));
    } else {
      o.config.push_back(text);
      o.config_keys.push_back(key);
    }
  }
  return o;
}

// The parsed file, its [sweep] and [[points]] tables taken out, `--set` applied.
struct Document {
  toml::table base;
  toml::table settings;
  std::optional<std::vector<toml::table>> points;
};

Document read_document(std::string_view text, const std::string& source, const Overrides& o) {
  Document d;
  d.base = parse_text(text, source);
  if (toml::node* s = d.base.get(kSweepTable)) {
    if (!s->is_table())
      throw InputError(fmt::format("{}: expected a table ([sweep])", where(source, *s, "sweep")));
    d.settings = std::move(*s->as_table());
    d.base.erase(kSweepTable);
  }
  for (const auto& [key, value] : o.settings) {
    toml::table parsed;
    try {
      parsed = toml::parse("v = " + value + "\n", "--set"sv);
    } catch (const toml::parse_error&) {
      parsed.insert("v", value);  // a bare word is a string, as for run's --set
    }
    move_into(d.settings, key, *parsed.get("v"));
  }
  if (toml::node* p = d.base.get(kPointsTable)) {
    auto* array = p->as_array();
    if (array == nullptr || !array->is_array_of_tables() || array->empty())
      throw InputError(
          fmt::format("{}: expected one or more [[points]] tables", where(source, *p, "points")));
    d.points.emplace();
    for (auto& entry : *array) d.points->push_back(std::move(*entry.as_table()));
    d.base.erase(kPointsTable);
  }
  apply_config_overrides(d.base, o.config);
  // An override wins over the [[points]] tables too.
  if (!d.points) return d;
  for (auto& entry : *d.points) {
    for (const auto& key : o.config_keys) {
      const auto dot = key.find('.');
      if (dot == std::string::npos) {
        entry.erase(key);
      } else if (auto* section = entry.get_as<toml::table>(key.substr(0, dot))) {
        section->erase(key.substr(dot + 1));
      }
    }
  }
  return d;
}

// The dotted keys a [[points]] table sets, with their nodes.
std::vector<std::pair<std::string, const toml::node*>> point_keys(const toml::table& entry,
                                                                  const std::string& source,
                                                                  std::size_t k) {
  std::vector<std::pair<std::string, const toml::node*>> keys;
  for (const auto& [section, node] : entry) {
    const auto* table = node.as_table();
    if (table == nullptr)
      throw InputError(fmt::format(
          "{}: expected keys of a section, e.g. friction.mu0 = 0.3 (in the [[points]] table {})",
          where(source, node, fmt::format("points.{}", section.str())), k + 1));
    for (const auto& [key, value] : *table)
      keys.emplace_back(fmt::format("{}.{}", section.str(), key.str()), &value);
  }
  return keys;
}

// The base with [[points]] table `entry` merged in (its values replace the base's).
toml::table merged(Document& d, std::optional<std::size_t> entry) {
  toml::table t = std::move(d.base);
  if (!entry) return t;
  for (auto& [section, node] : (*d.points)[*entry]) {
    toml::node* target = t.get(section.str());
    if (target == nullptr || !target->is_table())
      target = &t.insert_or_assign(section.str(), toml::table{}).first->second;
    for (auto& [key, value] : *node.as_table()) move_into(*target->as_table(), key.str(), value);
  }
  return t;
}

bool is_array_key(std::string_view key) {
  return std::find(kArrayKeys.begin(), kArrayKeys.end(), key) != kArrayKeys.end();
}

struct ListKey {
  std::string key;
  std::size_t size;
};

// The swept lists of a (merged) document, each with the node that holds it.
std::vector<std::pair<ListKey, const toml::node*>> lists_of(const toml::table& t,
                                                            const std::string& source) {
  std::vector<std::pair<ListKey, const toml::node*>> lists;
  for (const auto& [section, node] : t) {
    const auto* table = node.as_table();
    if (table == nullptr) continue;  // the config reader reports it
    for (const auto& [key, value] : *table) {
      const auto* array = value.as_array();
      if (array == nullptr) continue;
      const std::string dotted = fmt::format("{}.{}", section.str(), key.str());
      if (is_array_key(dotted)) {
        const bool list_of_arrays =
            !array->empty() && std::all_of(array->begin(), array->end(),
                                           [](const toml::node& e) { return e.is_array(); });
        if (!list_of_arrays) continue;  // a single value
      } else if (array->empty()) {
        throw InputError(
            fmt::format("{} = []: an empty list sweeps nothing", where(source, value, dotted)));
      }
      lists.push_back({ListKey{dotted, array->size()}, &value});
    }
  }
  return lists;
}

// Where a swept key first appears: keys of the file in file order, then those
// of --set overrides.
using Position = std::tuple<int, std::size_t, std::size_t, std::size_t>;
Position position(const toml::node& n, const std::string& source, std::size_t discovered) {
  if (!from_file(n, source)) return {1, 0, 0, discovered};
  return {0, n.source().begin.line, n.source().begin.column, discovered};
}

SweepSettings read_settings(const toml::table& t, const std::string& source,
                            const std::filesystem::path& base_dir) {
  SweepSettings s;
  for (const auto& [key, value] : t) {
    // A reference, not the structured binding, for the lambda to capture (a
    // binding captured by a lambda is C++20 that clang 14 lacks: scripts/fuzz.sh).
    const toml::node& node = value;
    const std::string name = fmt::format("sweep.{}", key.str());
    const auto fail = [&](std::string_view what) {
      throw InputError(
          fmt::format("{} = {}: {}", where(source, node, name),
                      node.is_string() ? *node.value<std::string>() : toml_value_text(node), what));
    };
    if (key.str() == "jobs") {
      const auto v = node.value_exact<std::int64_t>();
      if (!v) fail("expected an integer");
      if (*v < 0 || *v > 4096) fail("must be in [0, 4096] (0 = one per core)");
      s.jobs = static_cast<int>(*v);
    } else if (key.str() == "continuation" || key.str() == "stop_at_jam" ||
               key.str() == "confirm_jams") {
      const auto v = node.value_exact<bool>();
      if (!v) fail("expected true or false");
      (key.str() == "continuation"  ? s.continuation
       : key.str() == "stop_at_jam" ? s.stop_at_jam
                                    : s.confirm_jams) = *v;
    } else if (key.str() == "cold_start_phi") {
      const auto v = node.value_exact<std::string>();
      if (!v || (*v != "matched" && *v != "nominal" && *v != "bulk"))
        fail("expected \"nominal\", \"matched\" or \"bulk\"");
      s.cold_start_phi = *v == "matched" ? SweepSettings::ColdStartPhi::Matched
                         : *v == "bulk"  ? SweepSettings::ColdStartPhi::Bulk
                                         : SweepSettings::ColdStartPhi::Nominal;
    } else if (key.str() == "refines") {
      const auto v = node.value_exact<std::string>();
      if (!v || v->empty()) fail("expected the folder of a ramp sweep (its --out)");
      s.refines = std::filesystem::absolute(base_dir / *v).lexically_normal();
    } else if (key.str() == "continuation_strain" || key.str() == "continuation_transient_strain" ||
               key.str() == "extend_unsteady_to") {  // strains
      const auto v = node.value<double>();
      if (!v || !node.is_number()) fail("expected a number");
      if (!std::isfinite(*v)) fail("must be finite");
      if (key.str() != "continuation_transient_strain") {
        if (!(*v > 0.0)) fail("must be > 0");
        (key.str() == "continuation_strain" ? s.continuation_strain : s.extend_unsteady_to) = *v;
      } else {
        if (!(*v >= 0.0)) fail("must be >= 0");
        s.continuation_transient_strain = *v;
      }
    } else {
      std::vector<std::string> known(kSettingsKeys.begin(), kSettingsKeys.end());
      throw InputError(fmt::format("{}: unknown key{} (known in [sweep]: {})",
                                   where(source, node, name),
                                   did_you_mean(key.str(), kSettingsKeys), join(known, ", ")));
    }
  }
  if (!s.continuation)
    for (const auto name : {"continuation_strain"sv, "continuation_transient_strain"sv,
                            "stop_at_jam"sv, "confirm_jams"sv, "cold_start_phi"sv})
      if (const auto* node = t.get(name))
        throw InputError(
            fmt::format("{}: applies to continued points only, and sweep.continuation is false",
                        where(source, *node, fmt::format("sweep.{}", name))));
  return s;
}

// "friction.mu0 = 0.3, fluid.lambda = 10.0" for a message about a point.
std::string describe(const toml::table& point, const std::vector<std::string>& keys) {
  std::vector<std::string> parts;
  for (const auto& key : keys)
    if (const auto* value = find_key(point, key))
      parts.push_back(fmt::format("{} = {}", key, toml_value_text(*value)));
  return join(parts, ", ");
}

}  // namespace

SweepPlan parse_sweep(std::string_view text, std::string source,
                      const std::filesystem::path& base_dir,
                      const std::vector<std::string>& overrides) {
  const Overrides o = split_overrides(overrides);
  SweepPlan plan;
  plan.source = source;

  // The shape of the sweep: its groups (the whole file, or one per [[points]]
  // table), each group's lists, and the swept keys in file order.
  Document first = read_document(text, source, o);
  plan.settings = read_settings(first.settings, source, base_dir);
  if (const auto* scene = first.base.get("scene"))
    throw InputError(
        fmt::format("{}: sweeps run the shear cell ([cell]); a [scene] cannot be swept",
                    where(source, *scene, "scene")));
  const std::size_t groups = first.points ? first.points->size() : 1;
  std::vector<std::pair<Position, std::string>> found;
  std::vector<std::vector<ListKey>> group_lists(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    Document d = read_document(text, source, o);
    if (d.points)
      for (const auto& [key, node] : point_keys((*d.points)[g], source, g))
        found.emplace_back(position(*node, source, found.size()), key);
    const toml::table t = merged(d, d.points ? std::optional<std::size_t>(g) : std::nullopt);
    for (const auto& [list, node] : lists_of(t, source)) {
      found.emplace_back(position(*node, source, found.size()), list.key);
      group_lists[g].push_back(list);
    }
  }
  std::sort(found.begin(), found.end());
  for (const auto& [pos, key] : found)
    if (std::find(plan.keys.begin(), plan.keys.end(), key) == plan.keys.end())
      plan.keys.push_back(key);
  const auto rank = [&](const std::string& key) {
    return std::find(plan.keys.begin(), plan.keys.end(), key) - plan.keys.begin();
  };

  // The points: each group's grid, its first list slowest.
  std::map<std::string, std::size_t> seen;  // resolved config -> point
  for (std::size_t g = 0; g < groups; ++g) {
    auto& lists = group_lists[g];
    std::sort(lists.begin(), lists.end(),
              [&](const ListKey& a, const ListKey& b) { return rank(a.key) < rank(b.key); });
    std::size_t count = 1;
    for (const auto& l : lists) {
      count *= l.size;
      if (count > kMaxPoints)
        throw InputError(
            fmt::format("{}: more than {} points; check the lists", source, kMaxPoints));
    }
    std::vector<std::size_t> choice(lists.size(), 0);
    for (std::size_t n = 0; n < count; ++n) {
      Document d = read_document(text, source, o);
      toml::table t = merged(d, d.points ? std::optional<std::size_t>(g) : std::nullopt);
      for (std::size_t k = 0; k < lists.size(); ++k) {
        const auto dot = lists[k].key.find('.');
        auto& section = *t.get_as<toml::table>(lists[k].key.substr(0, dot));
        const std::string key = lists[k].key.substr(dot + 1);
        move_into(section, key, *section.get_as<toml::array>(key)->get(choice[k]));
      }
      const std::size_t index = plan.points.size();
      if (index >= kMaxPoints)
        throw InputError(
            fmt::format("{}: more than {} points; check the lists", source, kMaxPoints));
      SweepPoint p;
      p.index = index;
      try {
        p.config = config_from_table(t, source, base_dir);
      } catch (const InputError& e) {
        const std::string values = describe(t, plan.keys);
        throw InputError(
            fmt::format("{} (point {}{}{})", e.what(), index, values.empty() ? "" : ": ", values));
      }
      const auto [it, added] = seen.try_emplace(resolved_toml(p.config), index);
      if (!added)
        throw InputError(fmt::format("{}: points {} and {} are the same run ({})", source,
                                     it->second, index, describe(t, plan.keys)));
      plan.points.push_back(std::move(p));
      for (std::size_t k = lists.size(); k-- > 0;) {  // the odometer: last list fastest
        if (++choice[k] < lists[k].size) break;
        choice[k] = 0;
      }
    }
  }

  detail::name_points(plan);
  if (!plan.settings.refines.empty()) {
    if (!plan.settings.continuation)
      throw InputError(fmt::format(
          "{}: sweep.refines needs sweep.continuation = true (its points continue a ramp)",
          plan.source));
    detail::link_refinement(plan);
  } else if (plan.settings.continuation)
    detail::link_continuations(plan);
  detail::check_extension_cap(plan);
  return plan;
}

SweepPlan load_sweep(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parse_sweep(read_input_file(file, "sweep file"), file.string(), file.parent_path(),
                     overrides);
}

}  // namespace dilatant::sweep
