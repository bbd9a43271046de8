#pragma once
// Every configuration key, described once: section, name, the run mode it
// belongs to, type, unit, range and meaning, and how it is read from TOML and
// written back. Parsing, validation, `--set`, the resolved config.toml and the
// key list of `dilatant run --help` all work from this one table
// (io/config_keys.cpp). Defaults are the member initialisers of the structs in
// io/config.hpp; keys that constrain each other (radius_max >= radius_min,
// s_lim > s_c, transient_strain < strain) are checked after all are read.
#include <toml++/toml.h>

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/config.hpp"
#include "io/config_detail.hpp"

namespace dilatant {

// The run modes a key belongs to, as a set: a key of a mode the run is not in
// is an error, never silently ignored.
enum class RunMode : std::uint8_t {
  Cell = 1,
  Scene = 2,
  Sediment = 4,
  CellOrScene = Cell | Scene,
  Any = Cell | Scene | Sediment
};

struct ConfigKey {
  std::string_view section;  // "cell"
  std::string_view name;     // "phi"
  RunMode mode = RunMode::Any;
  std::string_view type;  // as a user would write it: "float", "[float, float, float]", ...
  std::string_view unit;  // "" for a pure number
  std::string range;      // the accepted values, e.g. "(0, 0.74)"; empty: any
  std::string_view doc;
  // Reads the key from its section into `config` (absent: keeps the default)
  // and checks its own range; throws InputError naming file, line and key. A
  // relative path is taken relative to `base_dir`.
  std::function<void(const config_detail::Section&, Config&, const std::filesystem::path& base_dir)>
      read;
  // The key's value in `config`, inserted into its section's table.
  std::function<void(const Config&, toml::table&)> write;

  std::string dotted() const { return std::string(section) + "." + std::string(name); }
  bool applies_to(RunMode m) const {
    return (static_cast<unsigned>(mode) & static_cast<unsigned>(m)) != 0;
  }
};

// The sections in documentation order, and every key in that order.
std::span<const std::string_view> config_sections();
std::span<const ConfigKey> config_keys();
const ConfigKey* find_config_key(std::string_view section, std::string_view name);
bool is_config_section(std::string_view section);
// The keys of one section, for messages ("known in [friction]: law, mu0, ...").
std::vector<std::string_view> config_key_names(std::string_view section);

// The mode a config is in, and how a user names it.
inline RunMode run_mode(const Config& c) {
  return c.cell() ? RunMode::Cell : c.scene() ? RunMode::Scene : RunMode::Sediment;
}
std::string_view mode_name(RunMode mode);  // "[cell]", "[scene]", "[sediment]", ...

// The key list of `dilatant run --help`: every key with its default, range,
// unit, the mode it belongs to, and its meaning.
std::string config_keys_help();

}  // namespace dilatant
