// The table of configuration keys (io/config_keys.hpp): one entry per key.
#include "io/config_keys.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "io/config_key_builders.hpp"
#include "io/input_error.hpp"

namespace dilatant {

void add_sediment_keys(std::vector<ConfigKey>& keys);  // io/config_keys_sediment.cpp

namespace {

using namespace config_key_builders;

// The words of friction.law (io/config.hpp).
constexpr std::array<std::pair<std::string_view, FrictionLawKind>, 3> kFrictionLaws = {{
    {"stribeck", FrictionLawKind::Stribeck},
    {"coulomb", FrictionLawKind::Coulomb},
    {"critical_load", FrictionLawKind::CriticalLoad},
}};

std::vector<ConfigKey> make_keys() {
  using enum RunMode;
  const auto positive = [](const Vec3& v) { return (v.array() > 0.0).all(); };
  const auto non_negative = [](const Vec3& v) { return (v.array() >= 0.0).all(); };
  std::vector<ConfigKey> k;
  // [cell]: stress-controlled simple shear between rough walls (docs/model.md "The shear cell").
  k.push_back(vec3("cell", "size", Cell, &cell, &CellConfig::size, +positive,
                   "every length must be > 0", "> 0 each", "R",
                   "Lx, Ly, Lz; periodic in x and y; Lz is the distance between the wall planes "
                   "(the box height, periodic too, under cell.boundary = \"lees-edwards\")"));
  k.push_back(integer("cell", "max_spheres", Cell, &cell, &CellConfig::max_spheres, 1,
                      std::numeric_limits<int>::max(), "must be >= 1", ">= 1",
                      "a cell.size and cell.phi estimated to hold more spheres (walls included) "
                      "are refused before the set-up; raise it to run a larger cell"));
  k.push_back(number("cell", "phi", Cell, &cell, &CellConfig::phi, open(0.0, 0.74), "",
                     "volume fraction of the mobile spheres, counted as cell.phi_definition says "
                     "(0.74: the densest packing of spheres)"));
  k.push_back(choice("cell", "phi_definition", Cell, &cell, &CellConfig::phi_definition,
                     {{"between-walls", PhiDefinition::BetweenWalls}, {"box", PhiDefinition::Box}},
                     "the volume cell.phi counts against: between the walls' mean surfaces, or "
                     "Lx Ly Lz (docs/model.md \"Volume fraction\"); summary.json reports both"));
  k.push_back(number("cell", "radius_min", Cell, &cell, &CellConfig::radius_min, above(0.0), "R",
                     "radii are uniform in [radius_min, radius_max]"));
  k.push_back(number("cell", "radius_max", Cell, &cell, &CellConfig::radius_max, Range{}, "R",
                     "the largest radius, R = 1 in code units (>= radius_min)"));
  k.push_back(ConfigKey{
      "cell", "seed", Cell, "integer", "", ">= 0", "random seed of the packing and the walls",
      [](const Section& s, Config& c, const std::filesystem::path&) {
        std::int64_t& v = cell(c).seed;
        v = s.integer("seed", v);
        config_detail::check(s, "seed", v, v >= 0, "must be >= 0");
      },
      [](const Config& c, toml::table& t) { t.insert("seed", cell(mut(c)).seed); }});
  k.push_back(number("cell", "shear_stress", Cell, &cell, &CellConfig::shear_stress, above(0.0),
                     "code units", "tau, the force per area driving the top wall"));
  k.push_back(number("cell", "wall_mass", Cell, &cell, &CellConfig::wall_mass,
                     at_least(0.0, " (0 = automatic)"), "rho_p R^3",
                     "mass of the top wall; 0 = the sum of its glued spheres' masses"));
  k.push_back(number("cell", "wall_friction", Cell, &cell, &CellConfig::wall_friction,
                     at_least(0.0), "",
                     "Coulomb friction of particle-wall contacts (the walls are rough glued "
                     "grains; docs/shear-cell.md)"));
  k.push_back(number("cell", "initial_shear_rate", Cell, &cell, &CellConfig::initial_shear_rate,
                     at_least(0.0), "sqrt(tau/rho_p)/R",
                     "start from the linear profile v_x = rate z (the wall at rate Lz); 0 = "
                     "from rest"));
  k.push_back(choice("cell", "boundary", Cell, &cell, &CellConfig::boundary,
                     {{"walls", CellBoundary::Walls}, {"lees-edwards", CellBoundary::LeesEdwards}},
                     "what bounds the cell in z: rough walls (the paper's cell), or Lees-Edwards "
                     "images, periodic in z with no walls (docs/shear-cell.md \"The Lees-Edwards "
                     "cell\"; there cell.phi counts Lx Ly Lz and the wall keys are errors)"));
  k.push_back(choice("cell", "control", Cell, &cell, &CellConfig::control,
                     {{"stress", ShearControl::Stress},
                      {"rate", ShearControl::Rate},
                      {"pressure", ShearControl::Pressure}},
                     "impose the shear stress cell.shear_stress (the boundary's speed follows), "
                     "or the shear rate cell.shear_rate (needs cell.boundary = \"lees-edwards\"; "
                     "the stress is measured), or the shear rate and the normal stress "
                     "cell.normal_stress (lees-edwards; the box height follows, docs/shear-cell.md "
                     "\"The pressure-imposed cell\")"));
  k.push_back(number("cell", "shear_rate", Cell, &cell, &CellConfig::shear_rate, at_least(0.0),
                     "sqrt(tau/rho_p)/R",
                     "gamma_dot imposed under cell.control = \"rate\" or \"pressure\" (> 0 "
                     "there; an error otherwise): the images above move at gamma_dot Lz"));
  k.push_back(number("cell", "normal_stress", Cell, &cell, &CellConfig::normal_stress,
                     at_least(0.0), "tau",
                     "P = -sigma_zz imposed under cell.control = \"pressure\" (> 0 there; an "
                     "error otherwise): the box height Lz follows it"));
  k.push_back(number("cell", "boundary_mass", Cell, &cell, &CellConfig::boundary_mass,
                     at_least(0.0, " (0 = automatic)"), "rho_p R^3",
                     "fictitious mass M of the Lees-Edwards boundary under stress control, "
                     "M dV/dt = Lx Ly (tau - sigma_zx), or of the box height under pressure "
                     "control, M dW/dt = Lx Ly (-sigma_zz - P); 0 = the mass the top wall of the "
                     "wall cell of the same size and seed has"));
  // [scene]: particles from a CSV file, planes, gravity (validation and teaching).
  k.push_back(ConfigKey{
      "scene", "particles", Scene, "string", "", "a CSV file",
      "required; id,x,y,z,r[,vx,vy,vz,wx,wy,wz,fixed] (io/particles_csv.hpp), relative to "
      "the config file's folder",
      [](const Section& s, Config& c, const std::filesystem::path& base_dir) {
        s.require("particles", "the CSV file of particles");
        const auto particles = s.string("particles", "");
        config_detail::check(s, "particles", particles, !particles.empty(), "must name a CSV file");
        // Absolute, so that the resolved config written elsewhere still points here.
        scene(c).particles = std::filesystem::absolute(base_dir / particles).lexically_normal();
      },
      [](const Config& c, toml::table& t) {
        t.insert("particles", scene(mut(c)).particles.string());
      }});
  k.push_back(vec3("scene", "gravity", Scene, &scene, &SceneConfig::gravity, nullptr, "", "",
                   "length/time^2", "acceleration of gravity"));
  k.push_back(vec3("scene", "box", Scene, &scene, &SceneConfig::box, +non_negative,
                   "lengths must be >= 0", ">= 0 each; > 0 on periodic axes", "length",
                   "box lengths, needed on periodic axes"));
  k.push_back(ConfigKey{"scene", "periodic", Scene, "[bool, bool, bool]", "", "",
                        "periodicity per axis",
                        [](const Section& s, Config& c, const std::filesystem::path&) {
                          scene(c).periodic = s.bool3("periodic", scene(c).periodic);
                        },
                        [](const Config& c, toml::table& t) {
                          const auto& p = scene(mut(c)).periodic;
                          t.insert("periodic", toml::array{p[0], p[1], p[2]});
                        }});
  k.push_back(number("scene", "trajectory_interval", Scene, &scene,
                     &SceneConfig::trajectory_interval, above(0.0), "time",
                     "time between frames of trajectory.csv"));
  k.push_back(ConfigKey{
      "scene", "planes", Scene, "[[scene.planes]] tables", "", "",
      "infinite fixed planes, each a point = [x, y, z] and a normal = [nx, ny, nz] pointing to "
      "the particles' side (non-zero; normalised on load)",
      [](const Section& s, Config& c, const std::filesystem::path&) {
        scene(c).planes = config_detail::read_planes(s);
      },
      [](const Config& c, toml::table& t) {
        toml::array planes;
        for (const auto& p : scene(mut(c)).planes)
          planes.push_back(
              toml::table{{"point", toml::array{p.point.x(), p.point.y(), p.point.z()}},
                          {"normal", toml::array{p.normal.x(), p.normal.y(), p.normal.z()}}});
        t.insert("planes", std::move(planes));
      }});
  add_sediment_keys(k);  // io/config_keys_sediment.cpp
  // [particles]
  k.push_back(ConfigKey{"particles", "density", CellOrScene, "float", "mass/length^3", "> 0",
                        "rho_p, the particles' density",
                        [](const Section& s, Config& c, const std::filesystem::path&) {
                          c.density = s.number("density", c.density);
                          config_detail::check(s, "density", c.density, c.density > 0.0,
                                               "must be > 0");
                        },
                        [](const Config& c, toml::table& t) { t.insert("density", c.density); }});
  // [friction] (docs/model.md "Friction"; paper Eq. 1)
  k.push_back(choice("friction", "law", Any, &friction, &FrictionConfig::law,
                     {kFrictionLaws.begin(), kFrictionLaws.end()},
                     "stribeck: BL or HD by the Sommerfeld number; coulomb: always mu0 (the "
                     "control without hydrodynamics); critical_load: frictionless below "
                     "friction.critical_load, mu0 from it on (Seto et al. 2013)"));
  k.push_back(number(
      "friction", "mu0", Any, &friction, &FrictionConfig::mu0, at_least(0.0), "",
      "boundary-lubricated friction coefficient (critical_load: from the critical load on)"));
  k.push_back(number("friction", "s_c", Any, &friction, &FrictionConfig::s_c,
                     Range{0.0, kSommerfeldMax, false, false, "5/(6 pi) ~ 0.2653",
                           ": the HD friction is positive only there"},
                     "", "Sommerfeld number of the BL -> HD switch"));
  k.push_back(number("friction", "s_lim", Any, &friction, &FrictionConfig::s_lim,
                     Range{-kInf, kSommerfeldMax, true, true, "5/(6 pi) ~ 0.2653",
                           ": the HD friction would be negative beyond"},
                     "", "where lubrication theory ends (> s_c); see beyond_s_lim"));
  k.push_back(choice("friction", "beyond_s_lim", Any, &friction,
                     &FrictionConfig::viscous_beyond_s_lim, {{"cap", false}, {"viscous", true}},
                     "cap: mu held at mu(s_lim) (the paper); viscous: mu(s_lim) s / s_lim, a "
                     "friction force linear in the sliding speed (friction/stribeck_law.hpp)"));
  k.push_back(number("friction", "critical_load", CellOrScene, &friction,
                     &FrictionConfig::critical_load, at_least(0.0, " (0 = none)"),
                     "eta_f^2/rho_p (cell), force (scene)",
                     "F*, the normal force from which a contact is frictional under law = "
                     "\"critical_load\" (> 0 there, 0 otherwise); a material constant: in a "
                     "cell the applied stress, lambda^2 in the paper's units, meets the onset "
                     "stress F*/R^2 at lambda = sqrt(F*/R^2) (docs/model.md \"Friction\")"));
  // [fluid]
  k.push_back(number("fluid", "lambda", Cell, &fluid, &FluidConfig::lambda, above(0.0), "",
                     "sqrt(tau rho_p) R / eta_f: the cell's eta_f = 1/lambda in code units"));
  k.push_back(number("fluid", "eta_f", Scene, &fluid, &FluidConfig::eta_f, at_least(0.0),
                     "the scene's units", "fluid viscosity (Stribeck law and fluid forces)"));
  k.push_back(choice("fluid", "lubrication", Any, &fluid, &FluidConfig::lubrication,
                     {{"none", LubricationKind::None}, {"normal", LubricationKind::Normal}},
                     "normal: squeeze film 6 pi eta_f a*^2 u_n / (h + delta) between close "
                     "surfaces, implicit (fluid/squeeze_film.hpp); none: the literal model"));
  k.push_back(number("fluid", "lubrication_cutoff", Any, &fluid, &FluidConfig::lubrication_cutoff,
                     above(0.0), "mean radii", "largest gap h with a squeeze film (LF-DEM: 0.5)"));
  k.push_back(number("fluid", "lubrication_regularization", Any, &fluid,
                     &FluidConfig::lubrication_regularization, above(0.0), "mean radii",
                     "delta, which keeps the film finite at contact (LF-DEM: 1e-3)"));
  k.push_back(
      choice("fluid", "drag", CellOrScene, &fluid, &FluidConfig::drag,
             {{"none", DragKind::None}, {"stokes", DragKind::Stokes}},
             "stokes: -6 pi eta_f r (v - U), torque -8 pi eta_f r^3 (w - Omega), U the "
             "walls' linear profile in a cell, at rest in a scene (fluid/stokes_drag.hpp)"));
  // [solver] (solver/contact_solver.hpp)
  k.push_back(number("solver", "dt", Any, &solver, &SolverConfig::dt,
                     at_least(0.0, " (0 = automatic)"), "time",
                     "time step; 0 = automatic (docs/model.md)"));
  k.push_back(choice("solver", "convergence", Any, &solver, &SolverConfig::convergence,
                     {{"residual", Convergence::Residual}, {"change", Convergence::Change}},
                     "residual: sweeps stop when no contact is further from its local answer "
                     "than tolerance x the load's impulse, tau (2R)^2 dt in a cell, weight x dt "
                     "in a scene; change: relative impulse change of one sweep (before 0.7)"));
  k.push_back(number("solver", "tolerance", Any, &solver, &SolverConfig::tolerance, open(0.0, 1.0),
                     "",
                     "of solver.convergence: largest residual per contact (default 1e-2), or "
                     "relative change"));
  k.push_back(integer("solver", "max_iterations", Any, &solver, &SolverConfig::max_iterations, 1,
                      std::numeric_limits<int>::max(), "must be >= 1", ">= 1",
                      "Gauss-Seidel sweeps per step at most"));
  k.push_back(number("solver", "max_displacement", Cell, &solver, &SolverConfig::max_displacement,
                     Range{0.0, 0.5, false, true, {}, {}}, "r_min",
                     "with dt = 0: the step keeps every body's move below this fraction of r_min"));
  k.push_back(choice("solver", "step_frame", Cell, &solver, &SolverConfig::step_frame,
                     {{"flow", StepFrame::MeanFlow}, {"lab", StepFrame::Lab}},
                     "with dt = 0, max_displacement bounds each body's move relative to the "
                     "drive's mean shear flow (flow: the steps per strain do not grow with the "
                     "cell's height) or in the lab frame (lab)"));
  k.push_back(integer("solver", "freeze_branches_after", Any, &solver,
                      &SolverConfig::freeze_branches_after, 0, std::numeric_limits<int>::max(),
                      "must be >= 0", ">= 0",
                      "sweeps after which each contact keeps its friction branch"));
  k.push_back(integer("solver", "threads", Any, &solver, &SolverConfig::threads, 0, 1024,
                      "must be in [0, 1024] (0 = all cores)", "[0, 1024]",
                      "threads sharing each sweep; 0 = all cores; results do not depend on it"));
  k.push_back(number("solver", "relaxation", Any, &solver, &SolverConfig::relaxation,
                     open(0.0, 2.0), "",
                     "over-relaxation of the normal impulses; same converged answer, fewer "
                     "sweeps (paper cell 229 -> 145 with coulomb 0.3); 1.6 stalls"));
  k.push_back(choice("solver", "acceleration", Any, &solver, &SolverConfig::acceleration,
                     {{"none", Acceleration::None}, {"cg", Acceleration::ConjugateGradient}},
                     "none: projected Gauss-Seidel sweeps; cg: the nonsmooth nonlinear conjugate "
                     "gradient on top of them (Silcowitz et al. 2010; same answer)"));
  k.push_back(
      boolean("solver", "skip_open_contacts", Any, &solver, &SolverConfig::skip_open_contacts,
              "sweeps between full ones visit only the contacts loaded after the last full "
              "sweep; same stopping test, on a full sweep (not with acceleration = \"cg\")"));
  k.push_back(boolean("solver", "redo_unconverged", Any, &solver, &SolverConfig::redo_unconverged,
                      "a step whose solve ends unconverged is redone at half its length, down to "
                      "1/64, and then stops the run (exit 1); false: accepted and counted "
                      "(docs/model.md)"));
  // [run]
  k.push_back(number("run", "strain", Cell, &run, &RunConfig::strain, at_least(0.0), "",
                     "total strain (> transient_strain)"));
  k.push_back(number("run", "time", Scene, &run, &RunConfig::time,
                     Range{0.0, kInf, false, true, {}, " in scene mode"}, "time",
                     "simulated time"));
  k.push_back(number("run", "transient_strain", Cell, &run, &RunConfig::transient_strain,
                     at_least(0.0), "", "strain excluded from the averages"));
  k.push_back(number("run", "output_interval", Cell, &run, &RunConfig::output_interval, above(0.0),
                     "", "strain between rows of timeseries.csv"));
  k.push_back(number("run", "checkpoint_interval", Cell, &run, &RunConfig::checkpoint_interval,
                     above(0.0), "", "strain between checkpoints"));
  k.push_back(number("run", "snapshot_interval", Cell, &run, &RunConfig::snapshot_interval,
                     at_least(0.0, " (0 = no ParaView snapshots)"), "",
                     "strain between ParaView snapshots; 0 = none"));
  return k;
}

constexpr std::string_view kSections[] = {"cell",     "scene", "sediment", "particles",
                                          "friction", "fluid", "solver",   "run"};

}  // namespace

std::string_view friction_law_name(FrictionLawKind law) {
  for (const auto& [word, value] : kFrictionLaws)
    if (value == law) return word;
  return "unknown";
}

std::span<const std::string_view> config_sections() { return kSections; }

std::span<const ConfigKey> config_keys() {
  static const std::vector<ConfigKey> keys = make_keys();
  return keys;
}

const ConfigKey* find_config_key(std::string_view section, std::string_view name) {
  for (const ConfigKey& k : config_keys())
    if (k.section == section && k.name == name) return &k;
  return nullptr;
}

bool is_config_section(std::string_view section) {
  for (std::string_view s : kSections)
    if (s == section) return true;
  return false;
}

std::vector<std::string_view> config_key_names(std::string_view section) {
  std::vector<std::string_view> names;
  for (const ConfigKey& k : config_keys())
    if (k.section == section) names.push_back(k.name);
  return names;
}

std::string_view mode_name(RunMode mode) {
  switch (mode) {
    case RunMode::Cell:
      return "[cell]";
    case RunMode::Scene:
      return "[scene]";
    case RunMode::Sediment:
      return "[sediment]";
    case RunMode::CellOrScene:
      return "[cell] and [scene]";
    case RunMode::Any:
      break;
  }
  return "any";
}

}  // namespace dilatant
