// The key list of `dilatant run --help`, written from the table of keys.
#include <fmt/format.h>

#include "io/config_keys.hpp"

namespace dilatant {

std::string config_keys_help() {
  Config cell_run;  // the defaults: a default-constructed Config is a [cell] run
  Config scene_run;
  scene_run.mode = SceneConfig{};
  Config sediment_run;
  sediment_run.mode = SedimentConfig{};
  sediment_run.friction.law = FrictionLawKind::Coulomb;
  std::string out =
      "Configuration keys (TOML). Exactly one of [cell] (the paper's shear cell), [scene] "
      "(particles from a CSV file) and [sediment] (dilatant jam) sets the run mode; a key of the "
      "other mode is an error. "
      "Every key has the default shown; lengths in R, times in R sqrt(rho_p/tau) in a cell.\n";
  std::string_view section;
  for (const ConfigKey& k : config_keys()) {
    if (k.section != section) {
      section = k.section;
      out += fmt::format("\n[{}]\n", section);
    }
    const Config& defaults = k.mode == RunMode::Scene      ? scene_run
                             : k.mode == RunMode::Sediment ? sediment_run
                                                           : cell_run;
    toml::table t;
    k.write(defaults, t);
    std::string value = toml_value_text(*t.get(k.name));
    if (k.section == "scene" && k.name == "particles") value = "(required)";
    const bool shared = k.section != "cell" && k.section != "scene";
    const std::string mode = shared && k.mode != RunMode::Any
                                 ? fmt::format(" ({} only)", mode_name(k.mode))
                                 : std::string();
    out += fmt::format("  {} = {}\n      {}{}{}{}{}\n", k.name, value, k.doc, mode,
                       k.range.empty() ? "" : "; range " + k.range,
                       k.unit.empty() ? "" : "; unit " + std::string(k.unit),
                       "; type " + std::string(k.type));
  }
  return out;
}

}  // namespace dilatant
