#include "io/config_compare.hpp"

#include <fmt/format.h>

#include <array>
#include <sstream>

namespace dilatant {
namespace {

std::string without_comments(const std::string& text) {
  std::istringstream lines(text);
  std::string out;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind('#', 0) != 0) out += line + "\n";
  return out;
}

// The first key whose value differs, as "key = a there, b here".
std::string first_difference(const std::string& there_text, const toml::table& here,
                             std::string_view here_name) {
  toml::table there;
  try {
    there = toml::parse(there_text);
  } catch (const toml::parse_error&) {
    return "its config.toml is not valid TOML";
  }
  const auto text = [](const toml::node* n) { return n ? toml_value_text(*n) : "(absent)"; };
  for (const toml::table* a : std::array<const toml::table*, 2>{&here, &there}) {
    for (const auto& [section, node] : *a) {
      const auto* table = node.as_table();
      if (table == nullptr) continue;
      for (const auto& [key, value] : *table) {
        const std::string dotted = fmt::format("{}.{}", section.str(), key.str());
        const toml::node* x = find_dotted_key(there, dotted);
        const toml::node* y = find_dotted_key(here, dotted);
        if (text(x) != text(y))
          return fmt::format("{} = {} there, {} {}", dotted, text(x), text(y), here_name);
      }
    }
  }
  return "its config.toml differs";
}

}  // namespace

const toml::node* find_dotted_key(const toml::table& resolved, std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) return resolved.get(key);
  const auto* section = resolved.get_as<toml::table>(key.substr(0, dot));
  return section ? section->get(key.substr(dot + 1)) : nullptr;
}

std::optional<std::string> config_difference(const std::string& file_text, const Config& config,
                                             std::string_view here) {
  if (without_comments(file_text) == without_comments(resolved_toml(config))) return std::nullopt;
  return first_difference(file_text, config.resolved, here);
}

}  // namespace dilatant
