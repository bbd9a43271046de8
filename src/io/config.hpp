#pragma once
// The run configuration: one struct per TOML section. Every key a user can set
// is described once, with its default (the member initialisers below, the one
// set of defaults), range, unit and meaning, in the table of io/config_keys.cpp;
// `dilatant run --help` prints that table. The file format is TOML.
//
// Units are code units. In the shear cell: the largest radius R = 1, the particle
// density rho_p = 1 and the applied shear stress tau = 1, so lengths are in R,
// times in R*sqrt(rho_p/tau), masses in rho_p*R^3 (measure/cell_units.hpp). In
// scene mode the numbers are in whatever consistent units the scene uses (e.g. SI).
//
// Exactly one of [cell] (the paper's shear cell), [scene] (particles from a
// CSV file, for validation and teaching) and [sediment] (`dilatant jam`) must
// be present: it is the run mode.
// Keys that belong to another mode are errors. Numbers must be finite;
// integers are accepted where a float is expected; unknown keys and
// out-of-range values are errors (InputError).
#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "friction/defaults.hpp"
#include "geometry/vec3.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant {

enum class FrictionLawKind { Stribeck, Coulomb, CriticalLoad };
// The word friction.law takes for it: "stribeck", "coulomb", "critical_load".
std::string_view friction_law_name(FrictionLawKind law);
// Fluid forces beyond the Stribeck friction (fluid/): none is the paper's literal model.
enum class LubricationKind { None, Normal };
enum class DragKind { None, Stokes };
// What cell.phi counts the mobile spheres' volume against.
enum class PhiDefinition { BetweenWalls, Box };
// What bounds the shear cell in z (docs/shear-cell.md "The Lees–Edwards cell"):
// rough walls, or Lees–Edwards images (periodic in z, no walls).
enum class CellBoundary { Walls, LeesEdwards };
// What the cell imposes: the shear stress (the boundary's speed follows), the
// shear rate (Lees–Edwards only; the stress is measured), or the shear rate
// and the normal stress (Lees–Edwards only; the box height follows, phi and
// the shear stress are measured).
enum class ShearControl { Stress, Rate, Pressure };

struct PlaneConfig {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit length after loading
};

struct SceneConfig {
  std::filesystem::path particles;  // absolute after loading
  Vec3 gravity{0.0, 0.0, -9.81};
  Vec3 box{0.0, 0.0, 0.0};
  std::array<bool, 3> periodic{false, false, false};
  double trajectory_interval = 0.01;
  std::vector<PlaneConfig> planes;
};

struct CellConfig {
  Vec3 size{25.0, 10.0, 27.0};
  double phi = 0.58;
  PhiDefinition phi_definition = PhiDefinition::BetweenWalls;
  double radius_min = 0.8;
  double radius_max = 1.0;
  std::int64_t seed = 1;
  double shear_stress = 1.0;
  double wall_mass = 0.0;
  double wall_friction = 1.0;
  double initial_shear_rate = 0.2;
  CellBoundary boundary = CellBoundary::Walls;
  ShearControl control = ShearControl::Stress;
  double shear_rate = 0.0;     // imposed under control = rate or pressure
  double normal_stress = 0.0;  // -sigma_zz imposed under control = pressure
  // Lees–Edwards stress control: the boundary's; pressure control: the box
  // height's. 0 = a top wall's mass
  double boundary_mass = 0.0;
  // A cell estimated to hold more spheres is refused before it is built
  // (io/config_parse.cpp): a mistyped size must not hang the set-up.
  int max_spheres = 1'000'000;
};

// Simulated centrifugation (`dilatant jam`, drivers/sediment.hpp): lengths in
// the largest radius R = 1, gravity g = 1, rho_p = 1.
struct SedimentConfig {
  Vec3 size{12.0, 12.0, 40.0};  // Lx, Ly (periodic), floor to lid
  double phi = 0.47;            // of the suspension before it settles (the paper's)
  double radius_min = 0.8;      // radii uniform in [radius_min, 1]
  std::int64_t seed = 1;        // samples use seed, seed + 1, ...
  int samples = 3;
  double stokes_number = 1e-3;  // g tau^2 / R, tau = 2 rho_p R^2 / (9 eta_f)
  double exclusion = 4.0;       // R left out at the floor and at the surface
  int max_spheres = 1'000'000;  // as CellConfig::max_spheres
};

// Defaults: the engine's own (friction/defaults.hpp, solver/contact_solver.hpp),
// so that a law or solver built without a config behaves as a default run.
struct FrictionConfig {
  FrictionLawKind law = FrictionLawKind::Stribeck;
  double mu0 = friction_defaults::kMu0;
  double s_c = friction_defaults::kSc;
  double s_lim = friction_defaults::kSlim;
  bool viscous_beyond_s_lim = false;  // beyond_s_lim = "viscous" (friction/stribeck_law.hpp)
  // F* of law = "critical_load" (friction/critical_load_law.hpp): in the shear
  // cell in the paper's force unit eta_f^2/rho_p, in a scene in its own units;
  // 0 (none) with every other law. Config::critical_load() converts it.
  double critical_load = 0.0;
};

struct FluidConfig {
  double lambda = 10.0;  // shear cell: eta_f = sqrt(tau rho_p) R / lambda
  double eta_f = 0.0;    // scene: the fluid viscosity itself
  // fluid/squeeze_film.hpp and fluid/stokes_drag.hpp; lengths in mean radii.
  // Off by default: the paper's literal model (docs/model.md "The default
  // model" says why, with the measurements).
  LubricationKind lubrication = LubricationKind::None;
  double lubrication_cutoff = 0.5;
  double lubrication_regularization = 1e-3;
  DragKind drag = DragKind::None;
};

// The frame the automatic step bounds each body's move in (solver.step_frame).
enum class StepFrame : std::uint8_t { MeanFlow, Lab };

struct SolverConfig {
  double dt = 0.0;  // 0 => automatic (drivers)
  // Runs stop on the contact problem's residual, in units of the applied
  // load's impulse (solver/contact_problem.hpp, docs/model.md "Convergence
  // criterion"); "change", the test before 0.7, is what an older resolved
  // config keeps.
  Convergence convergence = Convergence::Residual;
  double tolerance = 1e-2;
  int max_iterations = SolverSettings{}.max_iterations;
  double max_displacement = 0.02;  // automatic dt (cell): largest move per step / r_min
  // ... measured relative to the drive's mean flow, or in the lab frame
  // (before 0.8; drivers/cell_time_step.hpp).
  StepFrame step_frame = StepFrame::Lab;
  int freeze_branches_after = SolverSettings{}.freeze_branches_after;
  int threads = SolverSettings{}.threads;  // 0 => all cores (solver/slab_partition.hpp)
  double relaxation = SolverSettings::kRunRelaxation;
  Acceleration acceleration = SolverSettings{}.acceleration;
  bool skip_open_contacts = true;  // runs skip open contacts between full sweeps
  // Redo an unconverged step at half its length (SolverSettings); off until
  // the confined overlaps it meets are handled (docs/model.md "Unconverged steps").
  bool redo_unconverged = false;
};

struct RunConfig {
  double strain = 10.0;
  double time = 0.0;
  double transient_strain = 2.0;
  double output_interval = 0.05;
  double checkpoint_interval = 1.0;
  double snapshot_interval = 1.0;
};

struct Config {
  // The run mode: the paper's shear cell, a scene or a sediment.
  std::variant<CellConfig, SceneConfig, SedimentConfig> mode;
  double density = 1.0;  // [particles] density
  FrictionConfig friction;
  FluidConfig fluid;
  SolverConfig solver;
  RunConfig run;
  std::string source;  // file name used in messages ("<built-in>" for the default)
  // One line each that the user should read before the run (an older resolved
  // config loaded with the meaning its keys had): dilatant run prints them,
  // dilatant.load_config issues each as a UserWarning.
  std::vector<std::string> notes;
  toml::table resolved;  // every key with defaults filled in (= to_toml(*this) on load)

  // The mode's section, or null in the other modes.
  const CellConfig* cell() const { return std::get_if<CellConfig>(&mode); }
  CellConfig* cell() { return std::get_if<CellConfig>(&mode); }
  const SceneConfig* scene() const { return std::get_if<SceneConfig>(&mode); }
  SceneConfig* scene() { return std::get_if<SceneConfig>(&mode); }
  const SedimentConfig* sediment() const { return std::get_if<SedimentConfig>(&mode); }
  // The fluid viscosity the friction law uses, in code units: fluid.eta_f in a
  // scene; sqrt(tau rho_p) R / lambda in the shear cell (measure/cell_units.hpp).
  double fluid_viscosity() const;
  // The critical load the friction law uses, in code units: friction.critical_load
  // in a scene; in the shear cell friction.critical_load x eta_f^2 / rho_p
  // (= F*_paper tau R^2 / lambda^2), so that it stays one material force while
  // fluid.lambda moves the applied stress (docs/model.md "Friction").
  double critical_load() const;
};

// Reads `file`, applies `overrides`, validates. Throws InputError.
//
// Each override is "dotted.key=value" (from `--set`). The value is parsed as a
// TOML value (0.3, [10.0, 6.0, 12.0], "coulomb", true); text that is not a TOML
// value is taken as a string, so `friction.law=coulomb` works. The key must be
// a known key (section.key, or a whole section); it may create a section that
// the file lacks. Overrides apply in order, later ones win.
Config load_config(const std::filesystem::path& file, const std::vector<std::string>& overrides);

// The same from an in-memory TOML document. `source` names it in messages;
// a relative scene.particles is resolved against `base_dir`.
Config parse_config(std::string_view toml_text, std::string source,
                    const std::filesystem::path& base_dir,
                    const std::vector<std::string>& overrides);

// The same from a parsed TOML document, e.g. one point of a sweep: its nodes
// keep the source lines of the file they were parsed from, so messages name
// them as load_config's do ("sweep.toml:7: friction.mu0 = -0.1: must be >= 0").
// `source` names the file. No overrides are applied here.
Config config_from_table(const toml::table& root, std::string source,
                         const std::filesystem::path& base_dir);

// Applies `--set` overrides (as described for load_config) to a parsed document.
void apply_config_overrides(toml::table& root, const std::vector<std::string>& overrides);

// The built-in default run: the paper's shear cell at phi 0.58, mu0 0.1, Stribeck
// law (the literal model), every other key at its default; source "<built-in>". `overrides` work as
// for load_config (a relative scene.particles resolves against the working directory).
Config default_cell_config(const std::vector<std::string>& overrides = {});

// The configuration as a TOML table with every key present (what `resolved` holds).
// Built from the fields, so it reflects any change made after loading.
toml::table to_toml(const Config& c);

// One value of a configuration as TOML text: floats as the shortest text that
// reads back exactly and always with a '.' or exponent (0.1, 10.0, 5e-05),
// arrays as [a, b, c], strings quoted.
std::string toml_value_text(const toml::node& value);

// to_toml(c) as TOML text, headed by a comment; to be written next to results.
// parse_config of this text yields a Config with the same values.
std::string resolved_toml(const Config& c);
// Its first line, by which a loaded file is known as one (an older one may
// lack keys whose default has since changed: parse_config adds a note).
inline constexpr std::string_view kResolvedConfigHeader =
    "# dilatant: resolved configuration of this run";

}  // namespace dilatant
