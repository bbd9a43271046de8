// The resolved configuration: every key, defaults filled in, as TOML. Written
// next to the results so that a run can be repeated exactly from its output.
#include <fmt/format.h>

#include <sstream>

#include "io/config.hpp"
#include "io/config_detail.hpp"

namespace dilatant {
namespace {

toml::array array3(const Vec3& v) { return toml::array{v.x(), v.y(), v.z()}; }
toml::array array3(const std::array<bool, 3>& v) { return toml::array{v[0], v[1], v[2]}; }

}  // namespace

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
  toml::table t;
  if (c.cell) {
    const auto& cell = *c.cell;
    t.insert("cell", toml::table{{"size", array3(cell.size)},
                                 {"phi", cell.phi},
                                 {"radius_min", cell.radius_min},
                                 {"radius_max", cell.radius_max},
                                 {"seed", cell.seed},
                                 {"shear_stress", cell.shear_stress},
                                 {"wall_mass", cell.wall_mass},
                                 {"wall_friction", cell.wall_friction},
                                 {"initial_shear_rate", cell.initial_shear_rate}});
  }
  if (c.scene) {
    const auto& scene = *c.scene;
    toml::array planes;
    for (const auto& p : scene.planes)
      planes.push_back(toml::table{{"point", array3(p.point)}, {"normal", array3(p.normal)}});
    t.insert("scene", toml::table{{"particles", scene.particles.string()},
                                  {"gravity", array3(scene.gravity)},
                                  {"box", array3(scene.box)},
                                  {"periodic", array3(scene.periodic)},
                                  {"trajectory_interval", scene.trajectory_interval},
                                  {"planes", std::move(planes)}});
  }
  t.insert("particles", toml::table{{"density", c.density}});
  t.insert("friction",
           toml::table{{"law", c.friction.law == FrictionLawKind::Coulomb ? "coulomb" : "stribeck"},
                       {"mu0", c.friction.mu0},
                       {"s_c", c.friction.s_c},
                       {"s_lim", c.friction.s_lim}});
  t.insert("fluid", toml::table{{"lambda", c.fluid.lambda}, {"eta_f", c.fluid.eta_f}});
  t.insert("solver", toml::table{{"dt", c.solver.dt},
                                 {"tolerance", c.solver.tolerance},
                                 {"max_iterations", c.solver.max_iterations},
                                 {"max_displacement", c.solver.max_displacement},
                                 {"freeze_branches_after", c.solver.freeze_branches_after},
                                 {"threads", c.solver.threads},
                                 {"relaxation", c.solver.relaxation}});
  t.insert("run", toml::table{{"strain", c.run.strain},
                              {"time", c.run.time},
                              {"transient_strain", c.run.transient_strain},
                              {"output_interval", c.run.output_interval},
                              {"checkpoint_interval", c.run.checkpoint_interval},
                              {"snapshot_interval", c.run.snapshot_interval}});
  return t;
}

std::string resolved_toml(const Config& c) {
  // Written by hand from to_toml(c) rather than with toml++'s formatter: that one
  // prints doubles with 17 digits (0.57999999999999996) and sorts sections
  // alphabetically; here numbers are the shortest that read back exactly and the
  // order is that of the documentation.
  const auto t = to_toml(c);
  std::string out = fmt::format(
      "# dilatant: resolved configuration of this run (every key, defaults filled in;\n"
      "# keys and units are documented in src/io/config.hpp). Loaded from: {}\n",
      c.source);
  for (const auto& section : config_detail::schema()) {
    const auto* table = t.get_as<toml::table>(section.name);
    if (table == nullptr) continue;
    out += fmt::format("\n[{}]\n", section.name);
    const toml::array* planes = nullptr;
    for (const auto key : section.keys) {
      const auto* node = table->get(key);
      if (key == "planes")
        planes = node->as_array();  // must follow the plain keys
      else
        out += fmt::format("{} = {}\n", key, toml_value_text(*node));
    }
    for (std::size_t i = 0; planes && i < planes->size(); ++i) {
      out += "\n[[scene.planes]]\n";
      for (const auto key : config_detail::plane_keys())
        out +=
            fmt::format("{} = {}\n", key, toml_value_text(*planes->get(i)->as_table()->get(key)));
    }
  }
  return out;
}

}  // namespace dilatant
