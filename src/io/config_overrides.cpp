// `--set key=value` overrides, applied to the parsed TOML tree before it is read,
// so that an overridden value is validated exactly like one from the file.
#include <fmt/format.h>

#include "io/config_detail.hpp"
#include "io/config_keys.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant::config_detail {
namespace {

std::vector<std::string> split_key(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.emplace_back(trim(key.substr(start, dot - start)));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

// The value as TOML if it is a TOML value, else as a string: a bare word such
// as `coulomb` is what a user types on a command line.
toml::table parse_value(std::string_view value) {
  if (value.find_first_of("\r\n") == std::string_view::npos) {
    try {
      auto doc = toml::parse("v = " + std::string(value) + "\n", kOverrideSource);
      if (doc.size() == 1 && doc.contains("v")) return doc;
    } catch (const toml::parse_error&) {
      // not TOML: fall through to a string
    }
  }
  toml::table doc;
  doc.insert("v", std::string(value));
  return doc;
}

// Only known keys may be set, so a typo is reported as such and not as a key
// silently created (or as an unknown key in a section the file lacks).
void check_known(const std::vector<std::string>& parts, const std::string& key) {
  if (!is_config_section(parts[0]))
    throw InputError(fmt::format("--set {}: unknown section '{}'{} (known: {})", key, parts[0],
                                 did_you_mean(parts[0], config_sections()),
                                 join(config_sections())));
  if (parts.size() >= 2 && find_config_key(parts[0], parts[1]) == nullptr)
    throw InputError(fmt::format("--set {}: unknown key{} (known in [{}]: {})", key,
                                 did_you_mean(parts[1], config_key_names(parts[0])), parts[0],
                                 join(config_key_names(parts[0]))));
  if (parts.size() > 2)
    throw InputError(fmt::format("--set {}: '{}.{}' is not a table; set it as a whole", key,
                                 parts[0], parts[1]));
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& overrides) {
  for (const auto& text : overrides) {
    const auto eq = text.find('=');
    if (eq == std::string::npos)
      throw InputError(fmt::format("--set '{}': expected key=value", text));
    const std::string key(trim(std::string_view(text).substr(0, eq)));
    const auto parts = split_key(key);
    for (const auto& p : parts)
      if (p.empty()) throw InputError(fmt::format("--set '{}': malformed key '{}'", text, key));
    check_known(parts, key);

    auto doc = parse_value(trim(std::string_view(text).substr(eq + 1)));
    toml::table* target = &root;
    if (parts.size() == 2) {
      auto* section = root.get(parts[0]);
      if (section == nullptr) section = &root.insert(parts[0], toml::table{}).first->second;
      target = section->as_table();
      if (target == nullptr)
        throw InputError(fmt::format("--set {}: '{}' is not a table in the config", key, parts[0]));
    }
    // The node keeps its kOverrideSource origin: `where` reports it as "--set key".
    doc.get("v")->visit([&](auto&& v) { target->insert_or_assign(parts.back(), std::move(v)); });
  }
}

}  // namespace dilatant::config_detail
