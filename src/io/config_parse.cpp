// From TOML text to a validated Config. Each section is read by one function
// that states, next to each key, the range it must lie in (the ranges are the
// ones documented in config.hpp).
#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "io/config.hpp"
#include "io/config_detail.hpp"
#include "io/input_error.hpp"

namespace dilatant {
namespace {

using config_detail::check;
using config_detail::Section;

// The HD friction 2 pi s ln(5/(6 pi s)) is positive only below this.
constexpr double kSommerfeldMax = 5.0 / (6.0 * std::numbers::pi);

bool all_positive(const Vec3& v) { return (v.array() > 0.0).all(); }

CellConfig read_cell(const Section& s) {
  CellConfig c;
  s.reject_unknown(config_detail::find_section("cell")->keys);
  c.size = s.vec3("size", c.size);
  check(s, "size", c.size, all_positive(c.size), "every length must be > 0");
  c.phi = s.number("phi", c.phi);
  // 0.74 is the densest packing of spheres: nothing can flow at or above it.
  check(s, "phi", c.phi, c.phi > 0.0 && c.phi < 0.74, "must be in (0, 0.74)");
  c.radius_min = s.number("radius_min", c.radius_min);
  check(s, "radius_min", c.radius_min, c.radius_min > 0.0, "must be > 0");
  c.radius_max = s.number("radius_max", c.radius_max);
  check(s, "radius_max", c.radius_max, c.radius_max >= c.radius_min,
        fmt::format("must be >= cell.radius_min = {}", c.radius_min));
  c.seed = s.integer("seed", c.seed);
  check(s, "seed", c.seed, c.seed >= 0, "must be >= 0");
  c.shear_stress = s.number("shear_stress", c.shear_stress);
  check(s, "shear_stress", c.shear_stress, c.shear_stress > 0.0, "must be > 0");
  c.wall_mass = s.number("wall_mass", c.wall_mass);
  check(s, "wall_mass", c.wall_mass, c.wall_mass >= 0.0, "must be >= 0 (0 = automatic)");
  c.wall_friction = s.number("wall_friction", c.wall_friction);
  check(s, "wall_friction", c.wall_friction, c.wall_friction >= 0.0, "must be >= 0");
  c.initial_shear_rate = s.number("initial_shear_rate", c.initial_shear_rate);
  check(s, "initial_shear_rate", c.initial_shear_rate, c.initial_shear_rate >= 0.0, "must be >= 0");
  return c;
}

std::vector<PlaneConfig> read_planes(const Section& scene) {
  std::vector<PlaneConfig> planes;
  const auto* node = scene.find("planes");
  if (node == nullptr) return planes;
  const auto* array = node->as_array();
  if (array == nullptr || !(array->empty() || array->is_array_of_tables()))
    throw InputError(fmt::format("{}: expected an array of tables ([[scene.planes]])",
                                 config_detail::where(scene.source(), node, "scene.planes")));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const Section s(scene.source(), array->get(i), fmt::format("scene.planes[{}]", i));
    s.reject_unknown(config_detail::plane_keys());
    PlaneConfig p;
    s.require("point", "a plane needs a point and a normal");
    s.require("normal", "a plane needs a point and a normal");
    p.point = s.vec3("point", p.point);
    p.normal = s.vec3("normal", p.normal);
    check(s, "normal", p.normal, p.normal.norm() > 0.0, "must not be the zero vector");
    p.normal.normalize();
    planes.push_back(p);
  }
  return planes;
}

SceneConfig read_scene(const Section& s, const std::filesystem::path& base_dir) {
  SceneConfig c;
  s.reject_unknown(config_detail::find_section("scene")->keys);
  s.require("particles", "the CSV file of particles");
  const auto particles = s.string("particles", "");
  check(s, "particles", particles, !particles.empty(), "must name a CSV file");
  // Absolute, so that the resolved config written elsewhere still points here.
  c.particles = std::filesystem::absolute(base_dir / particles).lexically_normal();
  c.gravity = s.vec3("gravity", c.gravity);
  c.box = s.vec3("box", c.box);
  check(s, "box", c.box, (c.box.array() >= 0.0).all(), "lengths must be >= 0");
  c.periodic = s.bool3("periodic", c.periodic);
  for (int axis = 0; axis < 3; ++axis)
    check(s, "box", c.box, !c.periodic[static_cast<std::size_t>(axis)] || c.box[axis] > 0.0,
          fmt::format("axis {} is periodic (scene.periodic), so its length must be > 0",
                      "xyz"[axis]));
  c.trajectory_interval = s.number("trajectory_interval", c.trajectory_interval);
  check(s, "trajectory_interval", c.trajectory_interval, c.trajectory_interval > 0.0,
        "must be > 0");
  c.planes = read_planes(s);
  return c;
}

FrictionConfig read_friction(const Section& s) {
  FrictionConfig f;
  s.reject_unknown(config_detail::find_section("friction")->keys);
  const auto law = s.string("law", "stribeck");
  check(s, "law", law, law == "stribeck" || law == "coulomb",
        "must be \"stribeck\" or \"coulomb\"");
  f.law = law == "coulomb" ? FrictionLawKind::Coulomb : FrictionLawKind::Stribeck;
  f.mu0 = s.number("mu0", f.mu0);
  check(s, "mu0", f.mu0, f.mu0 >= 0.0, "must be >= 0");
  f.s_c = s.number("s_c", f.s_c);
  check(s, "s_c", f.s_c, f.s_c > 0.0 && f.s_c < kSommerfeldMax,
        "must be in (0, 5/(6 pi) ~ 0.2653): the HD friction is positive only there");
  f.s_lim = s.number("s_lim", f.s_lim);
  // Blame the key the user wrote: s_lim if given, else s_c.
  if (s.find("s_lim") || !s.find("s_c"))
    check(s, "s_lim", f.s_lim, f.s_lim > f.s_c, fmt::format("must be > friction.s_c = {}", f.s_c));
  else
    check(s, "s_c", f.s_c, f.s_c < f.s_lim, fmt::format("must be < friction.s_lim = {}", f.s_lim));
  check(s, "s_lim", f.s_lim, f.s_lim <= kSommerfeldMax,
        "must be <= 5/(6 pi) ~ 0.2653: the HD friction would be negative beyond");
  return f;
}

RunConfig read_run(const Section& s, bool cell_mode) {
  RunConfig r;
  s.reject_unknown(config_detail::find_section("run")->keys);
  r.strain = s.number("strain", r.strain);
  check(s, "strain", r.strain, r.strain >= 0.0, "must be >= 0");
  r.time = s.number("time", r.time);
  check(s, "time", r.time, r.time >= 0.0, "must be >= 0");
  if (!cell_mode) check(s, "time", r.time, r.time > 0.0, "must be > 0 in scene mode");
  r.transient_strain = s.number("transient_strain", r.transient_strain);
  check(s, "transient_strain", r.transient_strain, r.transient_strain >= 0.0, "must be >= 0");
  if (cell_mode) {
    const bool ok = r.transient_strain < r.strain;
    if (s.find("transient_strain") || !s.find("strain"))
      check(s, "transient_strain", r.transient_strain, ok,
            fmt::format("must be < run.strain = {}", r.strain));
    else
      check(s, "strain", r.strain, ok,
            fmt::format("must be > run.transient_strain = {}", r.transient_strain));
  }
  r.output_interval = s.number("output_interval", r.output_interval);
  check(s, "output_interval", r.output_interval, r.output_interval > 0.0, "must be > 0");
  r.checkpoint_interval = s.number("checkpoint_interval", r.checkpoint_interval);
  check(s, "checkpoint_interval", r.checkpoint_interval, r.checkpoint_interval > 0.0,
        "must be > 0");
  r.snapshot_interval = s.number("snapshot_interval", r.snapshot_interval);
  check(s, "snapshot_interval", r.snapshot_interval, r.snapshot_interval >= 0.0,
        "must be >= 0 (0 = no ParaView snapshots)");
  return r;
}

Config build(const toml::table& root, std::string source, const std::filesystem::path& base_dir) {
  for (const auto& [key, node] : root) {
    const auto where = config_detail::where(source, &node, key.str());
    if (config_detail::find_section(key.str()) == nullptr) {
      std::vector<std::string_view> names;
      for (const auto& s : config_detail::schema()) names.push_back(s.name);
      throw InputError(
          fmt::format("{}: unknown key (known sections: {})", where, config_detail::join(names)));
    }
    if (!node.is_table())
      throw InputError(fmt::format("{}: expected a table ([{}]), got {} {}", where, key.str(),
                                   config_detail::type_name(node), config_detail::show(node)));
  }
  const bool has_cell = root.contains("cell"), has_scene = root.contains("scene");
  if (has_cell && has_scene)
    throw InputError(
        fmt::format("{}: both [cell] and [scene] are present; use exactly one "
                    "([cell] = shear cell, [scene] = particles from a CSV file)",
                    source));
  if (!has_cell && !has_scene)
    throw InputError(
        fmt::format("{}: neither [cell] nor [scene] is present; use exactly one "
                    "([cell] = shear cell, [scene] = particles from a CSV file)",
                    source));
  auto section = [&](std::string_view name) {
    return Section(source, root.get(name), std::string(name));
  };

  Config c;
  if (has_cell) c.cell = read_cell(section("cell"));
  if (has_scene) c.scene = read_scene(section("scene"), base_dir);

  const auto particles = section("particles");
  particles.reject_unknown(config_detail::find_section("particles")->keys);
  c.density = particles.number("density", c.density);
  check(particles, "density", c.density, c.density > 0.0, "must be > 0");

  c.friction = read_friction(section("friction"));

  const auto fluid = section("fluid");
  fluid.reject_unknown(config_detail::find_section("fluid")->keys);
  c.fluid.lambda = fluid.number("lambda", c.fluid.lambda);
  check(fluid, "lambda", c.fluid.lambda, c.fluid.lambda > 0.0, "must be > 0");
  c.fluid.eta_f = fluid.number("eta_f", c.fluid.eta_f);
  check(fluid, "eta_f", c.fluid.eta_f, c.fluid.eta_f >= 0.0, "must be >= 0");

  const auto solver = section("solver");
  solver.reject_unknown(config_detail::find_section("solver")->keys);
  c.solver.dt = solver.number("dt", c.solver.dt);
  check(solver, "dt", c.solver.dt, c.solver.dt >= 0.0, "must be >= 0 (0 = automatic)");
  c.solver.tolerance = solver.number("tolerance", c.solver.tolerance);
  check(solver, "tolerance", c.solver.tolerance,
        c.solver.tolerance > 0.0 && c.solver.tolerance < 1.0, "must be in (0, 1)");
  const auto iterations = solver.integer("max_iterations", c.solver.max_iterations);
  check(solver, "max_iterations", iterations,
        iterations >= 1 && iterations <= std::numeric_limits<int>::max(), "must be >= 1");
  c.solver.max_iterations = static_cast<int>(iterations);
  c.solver.max_displacement = solver.number("max_displacement", c.solver.max_displacement);
  check(solver, "max_displacement", c.solver.max_displacement,
        c.solver.max_displacement > 0.0 && c.solver.max_displacement <= 0.5, "must be in (0, 0.5]");
  const auto freeze = solver.integer("freeze_branches_after", c.solver.freeze_branches_after);
  check(solver, "freeze_branches_after", freeze,
        freeze >= 0 && freeze <= std::numeric_limits<int>::max(), "must be >= 0");
  c.solver.freeze_branches_after = static_cast<int>(freeze);
  const auto threads = solver.integer("threads", c.solver.threads);
  check(solver, "threads", threads, threads >= 0 && threads <= 1024,
        "must be in [0, 1024] (0 = all cores)");
  c.solver.threads = static_cast<int>(threads);
  c.solver.relaxation = solver.number("relaxation", c.solver.relaxation);
  check(solver, "relaxation", c.solver.relaxation,
        c.solver.relaxation > 0.0 && c.solver.relaxation < 2.0, "must be in (0, 2)");

  c.run = read_run(section("run"), has_cell);
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
  return build(root, std::move(source), base_dir);
}

Config config_from_table(const toml::table& root, std::string source,
                         const std::filesystem::path& base_dir) {
  return build(root, std::move(source), base_dir);
}

void apply_config_overrides(toml::table& root, const std::vector<std::string>& overrides) {
  config_detail::apply_overrides(root, overrides);
}

Config load_config(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(
        fmt::format("{}: cannot read the config file ({})", file.string(),
                    std::filesystem::exists(file) ? "not a readable file" : "no such file"));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_config(text.str(), file.string(), file.parent_path(), overrides);
}

// The built-in run of `dilatant run` without a CONFIG: the paper's cell at
// phi 0.58, mu0 0.1, s_c 5e-5, at lambda = 100, where about 20% of the contacts
// are boundary lubricated (shear-thickened, Bagnold-like flow), for 4 strain
// units of which the last 2.5 are averaged: a first point in minutes. Its solver
// tolerance, 1e-4, is the one shown converged by tests/drivers/shear_cell_convergence_test.cpp.
Config default_cell_config(const std::vector<std::string>& overrides) {
  constexpr const char* kBuiltIn =
      "[cell]\n"
      "[fluid]\nlambda = 100.0\n"
      "[solver]\ntolerance = 1e-4\n"
      "[run]\nstrain = 4.0\ntransient_strain = 1.5\n";
  return parse_config(kBuiltIn, "<built-in>", std::filesystem::current_path(), overrides);
}

}  // namespace dilatant
