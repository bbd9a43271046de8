#pragma once
// The run configuration: every key a user can set, its unit, default and meaning,
// in one place. The file format is TOML (SPEC §2 "Configuration keys").
//
// Units are code units. In the shear cell: the largest radius R = 1, the particle
// density rho_p = 1 and the applied shear stress tau = 1, so lengths are in R,
// times in R*sqrt(rho_p/tau), masses in rho_p*R^3. In scene mode the numbers are
// in whatever consistent units the scene uses (e.g. SI).
//
// Exactly one of [cell] (the paper's shear cell) and [scene] (particles from a
// CSV file, for validation and teaching) must be present; the other sections
// are optional and every missing key takes the default written below.
//
//   [cell]                       stress-controlled simple shear between rough walls
//     size = [25.0, 10.0, 27.0]  Lx, Ly, Lz in R; periodic in x and y; Lz is the
//                                distance between the wall planes.         > 0
//     phi = 0.58                 volume fraction of the mobile spheres     (0, 0.74)
//     radius_min = 0.8           radii uniform in [radius_min, radius_max] > 0
//     radius_max = 1.0           (R = radius_max = 1 in code units)        >= radius_min
//     seed = 1                   random seed for the packing and walls     >= 0
//     shear_stress = 1.0         tau, force per area on the top wall       > 0
//     wall_mass = 0.0            mass of the top wall; 0 => sum of the
//                                masses of its glued spheres               >= 0
//     wall_friction = 1.0        Coulomb friction of particle-wall contacts (the walls
//                                are rough glued grains; see docs/shear-cell.md)  >= 0
//     initial_shear_rate = 0.2   start from the linear profile v_x = rate z (wall at
//                                rate Lz), in sqrt(tau/rho_p)/R; 0 = from rest  >= 0
//   [scene]                      anything else (validation, teaching)
//     particles = "p.csv"        required; CSV id,x,y,z,r[,vx,vy,vz,wx,wy,wz,fixed]
//                                (see io/particles_csv.hpp); a relative path is
//                                taken relative to the config file's directory
//     gravity = [0, 0, -9.81]    acceleration, length/time^2
//     box = [0, 0, 0]            box lengths; needed (> 0) on periodic axes >= 0
//     periodic = [false, false, false]   periodicity per axis
//     trajectory_interval = 0.01 time between rows of trajectory.csv       > 0
//     [[scene.planes]]           any number of infinite fixed planes
//       point = [x, y, z]        a point on the plane (required)
//       normal = [nx, ny, nz]    points to the particles' side (required,
//                                non-zero; normalised on load)
//   [particles]
//     density = 1.0              rho_p, mass per volume                    > 0
//   [friction]
//     law = "stribeck"           "stribeck" (BL/HD by Sommerfeld number) or
//                                "coulomb" (always mu0: the no-hydrodynamics control)
//     mu0 = 0.1                  boundary-lubricated friction coefficient  >= 0
//     s_c = 5e-5                 Sommerfeld number of the BL -> HD switch  (0, 5/(6 pi))
//     s_lim = 0.1                beyond it mu is held at mu(s_lim)          (s_c, 5/(6 pi)]
//                                (5/(6 pi) ~ 0.265: the HD law 2 pi s ln(5/(6 pi s))
//                                is positive only below it)
//   [fluid]
//     lambda = 10.0              shear cell: sqrt(tau*rho_p)*R/eta_f, so
//                                eta_f = 1/lambda in code units            > 0
//     eta_f = 0.0                scene: fluid viscosity in the scene's units
//                                (used by the Stribeck law only)           >= 0
//   [solver]
//     dt = 0.0                   time step; 0 => automatic (see drivers)   >= 0
//     tolerance = 1e-6           Gauss-Seidel stops when the relative change
//                                of all impulses is below it               (0, 1)
//     max_iterations = 1000      Gauss-Seidel sweeps per step at most      >= 1
//     max_displacement = 0.02    shear cell with dt = 0: dt keeps every body's move
//                                per step below this fraction of r_min     (0, 0.5]
//     freeze_branches_after = 50 sweeps after which each contact keeps its friction
//                                branch (solver/contact_solver.hpp)        >= 0
//     threads = 1                threads sharing each sweep; 0 => all cores;
//                                results do not depend on it. 1 by default:
//                                runs side by side (sweeps, ctest -j) would
//                                otherwise fight over the cores            [0, 1024]
//     relaxation = 1.3           over-relaxation of the normal impulses in the
//                                sweep; same converged answer, fewer sweeps:
//                                paper cell 229 -> 145 (coulomb 0.3), 92 -> 74
//                                (stribeck, lambda 100); 1.6 stalls        (0, 2)
//   [run]
//     strain = 10.0              shear cell: total strain                  >= 0
//     time = 0.0                 scene: simulated time (required > 0 there) >= 0
//     transient_strain = 2.0     shear cell: strain excluded from averages [0, strain)
//     output_interval = 0.05     between time-series rows: in strain (cell)
//                                or in time (scene)                        > 0
//     checkpoint_interval = 1.0  shear cell: strain between checkpoints     > 0
//     snapshot_interval = 1.0    shear cell: strain between ParaView snapshots
//                                (0 = none)                                >= 0
//
// Numbers must be finite; integers are accepted where a float is expected;
// unknown keys and out-of-range values are errors (InputError).
#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

enum class FrictionLawKind { Stribeck, Coulomb };

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
  double radius_min = 0.8;
  double radius_max = 1.0;
  std::int64_t seed = 1;
  double shear_stress = 1.0;
  double wall_mass = 0.0;
  double wall_friction = 1.0;
  double initial_shear_rate = 0.2;
};

struct FrictionConfig {
  FrictionLawKind law = FrictionLawKind::Stribeck;
  double mu0 = 0.1;
  double s_c = 5e-5;
  double s_lim = 0.1;
};

struct FluidConfig {
  double lambda = 10.0;
  double eta_f = 0.0;
};

struct SolverConfig {
  double dt = 0.0;
  double tolerance = 1e-6;
  int max_iterations = 1000;
  double max_displacement = 0.02;  // automatic dt (cell): largest move per step / r_min
  int freeze_branches_after = 50;  // sweeps before contacts keep their friction branch
  int threads = 1;                 // 0 => all cores (solver/slab_partition.hpp)
  double relaxation = 1.3;         // over-relaxation of normal impulses (SOR)
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
  std::optional<SceneConfig> scene;  // exactly one of scene and cell is present
  std::optional<CellConfig> cell;
  double density = 1.0;  // [particles] density
  FrictionConfig friction;
  FluidConfig fluid;
  SolverConfig solver;
  RunConfig run;
  std::string source;    // file name used in messages ("<built-in>" for the default)
  toml::table resolved;  // every key with defaults filled in (= to_toml(*this) on load)
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
// law, every other key at its default; source "<built-in>". `overrides` work as
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

}  // namespace dilatant
