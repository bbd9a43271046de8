// From TOML text to a validated Config: every key is read and range-checked by
// its entry in the table of keys (io/config_keys.cpp); the checks between keys
// follow here.
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "io/config.hpp"
#include "io/config_detail.hpp"
#include "io/config_keys.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant {
namespace {

using config_detail::check;
using config_detail::Section;

// Every table of the document is a known section; exactly one of [cell],
// [scene] and [sediment] sets the run mode.
RunMode check_sections(const toml::table& root, const std::string& source) {
  for (const auto& [key, node] : root) {
    const auto where = config_detail::where(source, &node, key.str());
    if (!is_config_section(key.str()))
      throw InputError(fmt::format("{}: unknown section{} (known sections: {})", where,
                                   did_you_mean(key.str(), config_sections()),
                                   config_detail::join(config_sections())));
    if (!node.is_table())
      throw InputError(fmt::format("{}: expected a table ([{}]), got {} {}", where, key.str(),
                                   config_detail::type_name(node), config_detail::show(node)));
  }
  const bool has_cell = root.contains("cell"), has_scene = root.contains("scene");
  std::vector<std::string> present;
  for (const auto* m : {"cell", "scene", "sediment"})
    if (root.contains(m)) present.push_back(fmt::format("[{}]", m));
  if (present.size() != 1) {
    const std::string what =
        present.empty()       ? std::string("neither [cell], [scene] nor [sediment] is present")
        : present.size() == 2 ? fmt::format("both {} and {} are present", present[0], present[1])
                              : std::string("[cell], [scene] and [sediment] are all present");
    throw InputError(fmt::format(
        "{}: {}; use exactly one ([cell] = shear cell, [scene] = particles from a CSV file, "
        "[sediment] = simulated centrifugation)",
        source, what));
  }
  return has_cell ? RunMode::Cell : has_scene ? RunMode::Scene : RunMode::Sediment;
}

// A key of the file must be a key of its section and of the run's mode: a key
// that the run would ignore is an error, never silently dropped.
void check_keys(const Section& s, std::string_view section, RunMode mode) {
  const auto names = config_key_names(section);
  s.reject_unknown(names);
  const auto* table = s.find_table();
  if (table == nullptr) return;
  for (const auto& [key, node] : *table) {
    const ConfigKey* k = find_config_key(section, key.str());
    if (k == nullptr || k->applies_to(mode)) continue;
    const bool eta_f = k->dotted() == "fluid.eta_f";
    throw InputError(fmt::format(
        "{}: not a key of a {} run (it belongs to {} runs){}",
        config_detail::where(s.source(), &node, k->dotted()), mode_name(mode), mode_name(k->mode),
        eta_f ? "; a [cell] run derives eta_f = sqrt(tau rho_p) R / fluid.lambda" : ""));
  }
}

// The keys of the cell's boundary and control (docs/shear-cell.md "The
// Lees–Edwards cell"). A key that means nothing for the chosen boundary or
// control is an error when set to anything but its default, never silently
// ignored; at its default (which means "none" or "automatic") it may stay, so
// that a resolved config, which lists every key, loads back.
void check_boundary_keys(const Section& s, const CellConfig& cell) {
  const CellConfig defaults;
  const bool le = cell.boundary == CellBoundary::LeesEdwards;
  const bool pressure = cell.control == ShearControl::Pressure;
  const bool rate = cell.control == ShearControl::Rate || pressure;
  if (!le) {
    check(s, "control", std::string(pressure ? "pressure" : "rate"), !rate,
          "needs cell.boundary = \"lees-edwards\" (the wall cell is stress-controlled)");
    check(s, "boundary_mass", cell.boundary_mass, cell.boundary_mass == defaults.boundary_mass,
          "is the Lees-Edwards boundary's mass: the wall cell's is cell.wall_mass");
  } else {
    const char* without_walls =
        "means nothing without walls (cell.boundary = \"lees-edwards\": cell.phi counts Lx Ly "
        "Lz)";
    check(s, "wall_mass", cell.wall_mass, cell.wall_mass == defaults.wall_mass, without_walls);
    check(s, "wall_friction", cell.wall_friction, cell.wall_friction == defaults.wall_friction,
          without_walls);
    if (cell.phi_definition != defaults.phi_definition)
      check(s, "phi_definition", *s.find("phi_definition"), false, without_walls);
    // z is periodic too: a sphere must not meet its own image (as x and y below).
    check(s, "size", cell.size, cell.size[2] >= 4.0 * cell.radius_max,
          fmt::format("Lz must be at least 4 largest radii ({}) on a periodic axis",
                      4.0 * cell.radius_max));
  }
  if (pressure) {
    check(s, "shear_rate", cell.shear_rate, cell.shear_rate > 0.0,
          "must be > 0 under cell.control = \"pressure\"");
    check(s, "normal_stress", cell.normal_stress, cell.normal_stress > 0.0,
          "must be > 0 under cell.control = \"pressure\"");
  } else {
    check(s, "normal_stress", cell.normal_stress, cell.normal_stress == defaults.normal_stress,
          "is imposed only under cell.control = \"pressure\"");
  }
  if (rate && !pressure) {
    check(s, "shear_rate", cell.shear_rate, cell.shear_rate > 0.0,
          "must be > 0 under cell.control = \"rate\"");
    check(s, "boundary_mass", cell.boundary_mass, cell.boundary_mass == defaults.boundary_mass,
          "means nothing under cell.control = \"rate\" (the boundary's speed is imposed)");
  } else if (!rate) {
    check(s, "shear_rate", cell.shear_rate, cell.shear_rate == defaults.shear_rate,
          "is imposed only under cell.control = \"rate\" (the stress is cell.shear_stress)");
  }
}

// The spheres a box of `size` holds at `phi` with radii uniform in
// [r_min, r_max] (mean volume (4/3) pi <r^3>, <r^3> = (r_max^4 - r_min^4) /
// (4 (r_max - r_min))), plus two wall monolayers, each at most Lx Ly / (2 r^2)
// spheres (a hexagonal layer of spheres of radius r holds Lx Ly / (2 sqrt(3) r^2)).
double estimated_spheres(const Vec3& size, double phi, double r_min, double r_max, bool walls) {
  const double r3 = r_max > r_min
                        ? (std::pow(r_max, 4) - std::pow(r_min, 4)) / (4.0 * (r_max - r_min))
                        : r_max * r_max * r_max;
  const double particles = phi * size[0] * size[1] * size[2] / (4.0 / 3.0 * std::numbers::pi * r3);
  return particles + (walls ? size[0] * size[1] / (r_max * r_max) : 0.0);
}

// A mistyped size (cell.size = [2000, 2000, 2000]) spun in the set-up for
// over 12 minutes, silent and deaf to SIGINT: refused here with the estimate.
void check_sphere_count(const Section& s, const Vec3& size, double estimate, int limit,
                        std::string_view section) {
  check(s, "size", size, estimate <= static_cast<double>(limit),
        fmt::format("holds about {:.3g} spheres, more than {}.max_spheres = {} (raise it to run "
                    "a cell this large)",
                    estimate, section, limit));
}

// Whether the user wrote `key`: an override, or a line of their own file (the
// built-in default cell's lines are ours: `--set run.strain=0` must be blamed
// on run.strain, not on the built-in run.transient_strain).
bool user_wrote(const Section& s, std::string_view key) {
  const toml::node* n = s.find(key);
  if (n == nullptr) return false;
  const auto& src = n->source();
  const bool override =
      src.begin.line == 0 || (src.path && *src.path == config_detail::kOverrideSource);
  return override || s.source() != config_detail::kBuiltInSource;
}

// Keys that constrain each other, checked once all are read. The message blames
// the key the user wrote (the later one if both were written).
void check_constraints(const std::function<Section(std::string_view)>& section, const Config& c) {
  if (const CellConfig* cell = c.cell()) {
    const Section s = section("cell");
    const bool radii_ok = cell->radius_max >= cell->radius_min;
    if (user_wrote(s, "radius_min") && !user_wrote(s, "radius_max"))
      check(s, "radius_min", cell->radius_min, radii_ok,
            fmt::format("must be <= cell.radius_max = {}", cell->radius_max));
    else
      check(s, "radius_max", cell->radius_max, radii_ok,
            fmt::format("must be >= cell.radius_min = {}", cell->radius_min));
    // Periodic in x and y: a sphere must not meet its own image, and the cell
    // list needs at least 4 largest radii per periodic axis (as a scene's box).
    const double min_side = 4.0 * cell->radius_max;
    for (int axis = 0; axis < 2; ++axis) {
      const char* name = axis == 0 ? "Lx" : "Ly";
      check(s, "size", cell->size, cell->size[axis] >= min_side,
            fmt::format("{} must be at least 4 largest radii ({}) on a periodic axis", name,
                        min_side));
    }
    check_boundary_keys(s, *cell);
    check_sphere_count(s, cell->size,
                       estimated_spheres(cell->size, cell->phi, cell->radius_min, cell->radius_max,
                                         cell->boundary == CellBoundary::Walls),
                       cell->max_spheres, "cell");
    const Section r = section("run");
    const bool ok = c.run.transient_strain < c.run.strain;
    if (user_wrote(r, "transient_strain") || !user_wrote(r, "strain"))
      check(r, "transient_strain", c.run.transient_strain, ok,
            fmt::format("must be < run.strain = {}", c.run.strain));
    else
      check(r, "strain", c.run.strain, ok,
            fmt::format("must be > run.transient_strain = {}", c.run.transient_strain));
  }
  if (const SceneConfig* scene = c.scene()) {
    const Section fl = section("fluid");
    // A fluid force asked for in a fluid without viscosity would silently be
    // none (dry scenes: see dry_scene_has_no_fluid_forces).
    if (c.fluid.eta_f <= 0.0) {
      if (fl.find("drag"))
        check(fl, "drag", "stokes", c.fluid.drag == DragKind::None, "needs fluid.eta_f > 0");
      if (fl.find("lubrication"))
        check(fl, "lubrication", "normal", c.fluid.lubrication == LubricationKind::None,
              "needs fluid.eta_f > 0");
    }
    const Section s = section("scene");
    for (int axis = 0; axis < 3; ++axis)
      check(s, "box", scene->box,
            !scene->periodic[static_cast<std::size_t>(axis)] || scene->box[axis] > 0.0,
            fmt::format("axis {} is periodic (scene.periodic), so its length must be > 0",
                        "xyz"[axis]));
  }
  if (const SedimentConfig* sediment = c.sediment())
    check_sphere_count(
        section("sediment"), sediment->size,
        estimated_spheres(sediment->size, sediment->phi, sediment->radius_min, 1.0, false),
        sediment->max_spheres, "sediment");
  const Section f = section("friction");
  const FrictionConfig& fr = c.friction;
  if (c.sediment() != nullptr)
    check(f, "law", std::string(friction_law_name(fr.law)), fr.law == FrictionLawKind::Coulomb,
          "a sediment's contacts are boundary lubricated: use \"coulomb\" with friction.mu0");
  // friction.critical_load belongs to law = "critical_load", which needs it.
  if (fr.law == FrictionLawKind::CriticalLoad) {
    if (f.find("critical_load"))
      check(f, "critical_load", fr.critical_load, fr.critical_load > 0.0,
            "must be > 0 with friction.law = \"critical_load\"");
    else
      check(f, "law", std::string(friction_law_name(fr.law)), fr.critical_load > 0.0,
            "needs friction.critical_load > 0, the critical normal force (in eta_f^2/rho_p in "
            "a cell)");
  } else {
    check(f, "critical_load", fr.critical_load, fr.critical_load == 0.0,
          fmt::format("means nothing with friction.law = \"{}\" (it is the threshold of "
                      "\"critical_load\")",
                      friction_law_name(fr.law)));
  }
  if (f.find("s_lim") || !f.find("s_c"))
    check(f, "s_lim", fr.s_lim, fr.s_lim > fr.s_c,
          fmt::format("must be > friction.s_c = {}", fr.s_c));
  else
    check(f, "s_c", fr.s_c, fr.s_c < fr.s_lim,
          fmt::format("must be < friction.s_lim = {}", fr.s_lim));
}

Config build(const toml::table& root, std::string source, const std::filesystem::path& base_dir) {
  const RunMode mode = check_sections(root, source);
  const auto section = [&](std::string_view name) {
    return Section(source, root.get(name), std::string(name));
  };
  Config c;
  if (mode == RunMode::Scene) c.mode = SceneConfig{};
  // A sediment's contacts are boundary lubricated (the paper centrifuges at
  // about 2000 g): Coulomb friction is its law, and the only one it accepts.
  if (mode == RunMode::Sediment)
    c.mode = SedimentConfig{}, c.friction.law = FrictionLawKind::Coulomb;
  for (std::string_view name : config_sections()) {
    if (name == "cell" && mode != RunMode::Cell) continue;
    if (name == "scene" && mode != RunMode::Scene) continue;
    if (name == "sediment" && mode != RunMode::Sediment) continue;
    const Section s = section(name);
    check_keys(s, name, mode);
    for (const ConfigKey& k : config_keys())
      if (k.section == name && k.applies_to(mode)) k.read(s, c, base_dir);
  }
  check_constraints(section, c);
  // A scene without a viscosity is dry: the default fluid forces do not apply,
  // and its resolved config says so (and reads back as the same run).
  if (c.scene() != nullptr && c.fluid.eta_f <= 0.0) {
    c.fluid.drag = DragKind::None;
    c.fluid.lubrication = LubricationKind::None;
  }
  c.source = std::move(source);
  c.resolved = to_toml(c);
  return c;
}

}  // namespace

Config parse_config(std::string_view toml_text, std::string source,
                    const std::filesystem::path& base_dir,
                    const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: invalid TOML: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  config_detail::apply_overrides(root, overrides);
  // A resolved config written before solver.convergence existed (0.6 and
  // older) lists solver.tolerance as a relative change: it keeps that meaning,
  // said in one line, so that an old run's folder runs as it did.
  std::string note;
  if (toml_text.starts_with(kResolvedConfigHeader)) {
    toml::table* solver = root.get_as<toml::table>("solver");
    if (solver != nullptr && solver->contains("tolerance") && !solver->contains("convergence")) {
      solver->insert("convergence", "change");
      note = fmt::format(
          "note: {} was written before solver.convergence; its solver.tolerance = {} keeps its "
          "old meaning (relative change of one sweep); set solver.convergence = \"residual\" "
          "for the load-scaled residual (docs/model.md \"Convergence criterion\")",
          source, config_detail::show(*solver->get("tolerance")));
    }
  }
  Config c = build(root, std::move(source), base_dir);
  if (!note.empty()) c.notes.push_back(std::move(note));
  return c;
}

Config config_from_table(const toml::table& root, std::string source,
                         const std::filesystem::path& base_dir) {
  return build(root, std::move(source), base_dir);
}

void apply_config_overrides(toml::table& root, const std::vector<std::string>& overrides) {
  config_detail::apply_overrides(root, overrides);
}

Config load_config(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parse_config(read_input_file(file, "config file"), file.string(), file.parent_path(),
                      overrides);
}

// The built-in run of `dilatant run` without a CONFIG: the paper's cell at
// phi 0.58, mu0 0.1, s_c 5e-5 (the literal model), at lambda = 100 (tau = 10^4
// in the paper's units: thickened, about 20% of the contacts boundary
// lubricated), from a new packing for 12 strain units of which the last 6 are
// averaged. Shorter cold starts are not steady or not linear: 4 strain (avg.
// 1.5-4) and 8 (avg. 4-8) left the central shear rate 11-18% below the no-slip
// value; lambda 50 with 8 strain 14% (docs/paper-reproduction.md "The Newtonian
// branch", item 3). Its solver tolerance is the default residual's, shown
// converged by tests/drivers/shear_cell_convergence_test.cpp.
Config default_cell_config(const std::vector<std::string>& overrides) {
  constexpr const char* kBuiltIn =
      "[cell]\n"
      "[fluid]\nlambda = 100.0\n"
      "[run]\nstrain = 12.0\ntransient_strain = 6.0\n";
  return parse_config(kBuiltIn, std::string(config_detail::kBuiltInSource),
                      std::filesystem::current_path(), overrides);
}

}  // namespace dilatant
