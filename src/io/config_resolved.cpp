// The resolved configuration: every key, defaults filled in, as TOML. Written
// next to the results so that a run can be repeated exactly from its output.
#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "io/config.hpp"
#include "io/config_detail.hpp"
#include "io/config_keys.hpp"
#include "measure/cell_units.hpp"

namespace dilatant {
std::string toml_value_text(const toml::node& n) {
  if (const auto* d = n.as_floating_point()) {
    auto text = fmt::format("{}", d->get());  // shortest text that reads back exactly
    if (text.find_first_of(".e") == std::string::npos) text += ".0";  // stay a float
    return text;
  }
  if (const auto* a = n.as_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < a->size(); ++i)
      text += (i ? ", " : "") + toml_value_text(*a->get(i));
    return text + "]";
  }
  std::ostringstream os;  // strings (escaped by toml++), integers, booleans
  n.visit([&](const auto& v) { os << v; });
  return os.str();
}

toml::table to_toml(const Config& c) {
  const RunMode mode = run_mode(c);
  toml::table t;
  for (std::string_view section : config_sections()) {
    toml::table table;
    for (const ConfigKey& k : config_keys())
      if (k.section == section && k.applies_to(mode)) k.write(c, table);
    if (!table.empty()) t.insert(section, std::move(table));
  }
  return t;
}

namespace {

// Lines of comment after [friction] under law = "critical_load": F* in code
// units, the onset stress sigma* = F*/R^2 in the paper's units and over the
// applied stress, and the lambda at which the applied stress equals it
// (tau_paper = lambda^2; measure/cell_units.hpp).
std::string critical_load_comment(const Config& c) {
  const CellConfig& cell = *c.cell();
  const CellUnits u =
      make_cell_units(cell.shear_stress, c.density, cell.radius_max, c.fluid.lambda);
  const double sigma_star = c.critical_load() / (cell.radius_max * cell.radius_max);
  const auto text = [](double v) { return toml_value_text(toml::value<double>(v)); };
  return fmt::format(
      "# critical_load in code units = {}  (derived: critical_load eta_f^2 / density)\n"
      "# onset stress sigma* = critical_load / radius_max^2 = {} (paper's units) = {} x "
      "shear_stress; the applied stress reaches it at lambda = {}\n",
      text(c.critical_load()), text(sigma_star / u.stress_unit),
      text(sigma_star / cell.shear_stress),
      text(c.fluid.lambda * std::sqrt(sigma_star / cell.shear_stress)));
}

}  // namespace

double Config::fluid_viscosity() const {
  if (const CellConfig* c = cell())
    return make_cell_units(c->shear_stress, density, c->radius_max, fluid.lambda).eta_f;
  return fluid.eta_f;
}

double Config::critical_load() const {
  if (const CellConfig* c = cell())
    return friction.critical_load *
           make_cell_units(c->shear_stress, density, c->radius_max, fluid.lambda).force_unit;
  return friction.critical_load;
}

std::string resolved_toml(const Config& c) {
  // Written by hand from to_toml(c) rather than with toml++'s formatter: that one
  // prints doubles with 17 digits (0.57999999999999996) and sorts sections
  // alphabetically; here numbers are the shortest that read back exactly and the
  // order is that of the documentation.
  const auto t = to_toml(c);
  std::string out = fmt::format(
      "{} (every key, defaults filled in;\n"
      "# keys and units: `dilatant run --help`). Loaded from: {}\n",
      kResolvedConfigHeader, c.source);
  for (std::string_view section : config_sections()) {
    const auto* table = t.get_as<toml::table>(section);
    if (table == nullptr) continue;
    out += fmt::format("\n[{}]\n", section);
    const toml::array* planes = nullptr;
    for (const ConfigKey& k : config_keys()) {
      if (k.section != section || !table->contains(k.name)) continue;
      const auto* node = table->get(k.name);
      if (k.name == "planes")
        planes = node->as_array();  // must follow the plain keys
      else
        out += fmt::format("{} = {}\n", k.name, toml_value_text(*node));
    }
    // The cell derives the fluid viscosity from lambda: show the value used,
    // as a comment (it is not a key of a [cell] run).
    if (section == "fluid" && c.cell())
      out +=
          fmt::format("# eta_f = {}  (derived: sqrt(shear_stress density) radius_max / lambda)\n",
                      toml_value_text(toml::value<double>(c.fluid_viscosity())));
    // The critical load in code units, and the onset stress it sets.
    if (section == "friction" && c.cell() && c.friction.law == FrictionLawKind::CriticalLoad)
      out += critical_load_comment(c);
    for (std::size_t i = 0; planes && i < planes->size(); ++i) {
      out += "\n[[scene.planes]]\n";
      for (const auto key : {"point", "normal"})
        out +=
            fmt::format("{} = {}\n", key, toml_value_text(*planes->get(i)->as_table()->get(key)));
    }
  }
  return out;
}

}  // namespace dilatant
