#include "io/config_compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <type_traits>
#include <variant>

#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant {
namespace {

std::string without_comments(const std::string& text) {
  std::istringstream lines(text);
  std::string out;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind('#', 0) != 0) out += line + "\n";
  return out;
}

// The first key not in `ignored` whose value differs, as "key = a there, b
// here"; nullopt when there is none.
std::optional<std::string> first_difference(const toml::table& there, const toml::table& here,
                                            std::string_view here_name,
                                            std::span<const std::string_view> ignored) {
  const auto text = [](const toml::node* n) { return n ? toml_value_text(*n) : "(absent)"; };
  for (const toml::table* a : std::array<const toml::table*, 2>{&here, &there}) {
    for (const auto& [section, node] : *a) {
      const auto* table = node.as_table();
      if (table == nullptr) continue;
      for (const auto& [key, value] : *table) {
        const std::string dotted = fmt::format("{}.{}", section.str(), key.str());
        if (std::find(ignored.begin(), ignored.end(), dotted) != ignored.end()) continue;
        const toml::node* x = find_dotted_key(there, dotted);
        const toml::node* y = find_dotted_key(here, dotted);
        if (text(x) != text(y))
          return fmt::format("{} = {} there, {} {}", dotted, text(x), text(y), here_name);
      }
    }
  }
  return std::nullopt;
}

void erase_dotted_key(toml::table& table, std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) {
    table.erase(key);
    return;
  }
  if (auto* section = table.get_as<toml::table>(key.substr(0, dot)))
    section->erase(key.substr(dot + 1));
}

// The resolved defaults of config's mode: every key at the value a
// configuration that does not set it gets.
toml::table mode_defaults(const Config& config) {
  Config d;
  d.mode = std::visit(
      [](const auto& m) -> decltype(Config::mode) { return std::decay_t<decltype(m)>{}; },
      config.mode);
  return to_toml(d);
}

// A key that a run's config.toml lacks and that `here` holds at its default
// is filled in: a run of an older version, which did not write that key, ran
// with the behaviour the key's default keeps (a key is added with the default
// that leaves earlier runs unchanged, e.g. cell.normal_stress in 0.9.0).
void fill_absent_defaults(toml::table& there, const toml::table& here,
                          const toml::table& defaults) {
  for (const auto& [section, node] : here) {
    const auto* table = node.as_table();
    if (table == nullptr) continue;
    for (const auto& [key, value] : *table) {
      const std::string dotted = fmt::format("{}.{}", section.str(), key.str());
      if (find_dotted_key(there, dotted) != nullptr) continue;
      const toml::node* d = find_dotted_key(defaults, dotted);
      if (d == nullptr || toml_value_text(*d) != toml_value_text(value)) continue;
      auto* there_section = there.get_as<toml::table>(section.str());
      if (there_section == nullptr) continue;  // a section the run did not have: a difference
      there_section->insert(key.str(), value);
    }
  }
}

}  // namespace

const toml::node* find_dotted_key(const toml::table& resolved, std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) return resolved.get(key);
  const auto* section = resolved.get_as<toml::table>(key.substr(0, dot));
  return section ? section->get(key.substr(dot + 1)) : nullptr;
}

std::optional<std::string> config_difference(const std::string& file_text, const Config& config,
                                             std::string_view here,
                                             std::span<const std::string_view> ignored) {
  if (without_comments(file_text) == without_comments(resolved_toml(config))) return std::nullopt;
  toml::table there;
  try {
    there = toml::parse(file_text);
  } catch (const toml::parse_error&) {
    return "its config.toml is not valid TOML";
  }
  fill_absent_defaults(there, config.resolved, mode_defaults(config));
  // The same configuration once the ignored keys are taken out of both.
  toml::table filled = there, mine = config.resolved;
  for (const std::string_view key : ignored) {
    erase_dotted_key(filled, key);
    erase_dotted_key(mine, key);
  }
  std::ostringstream a, b;
  a << filled;
  b << mine;
  if (a.str() == b.str()) return std::nullopt;
  return first_difference(there, config.resolved, here, ignored)
      .value_or("its config.toml differs");
}

std::optional<toml::table> resumable_run_config(const std::filesystem::path& folder,
                                                const Config& config,
                                                std::span<const std::string_view> extensible,
                                                std::string_view may_change) {
  const auto written = folder / "config.toml";
  if (!std::filesystem::is_regular_file(written)) return std::nullopt;
  const std::string text = read_input_file(written, "run's configuration");
  if (const auto difference = config_difference(text, config, "here", extensible))
    throw InputError(
        fmt::format("{}: the run there has another configuration ({}): resume it with the same "
                    "configuration and --set options ({}), or choose another --out",
                    written.string(), *difference, may_change));
  return toml::parse(text);
}

}  // namespace dilatant
