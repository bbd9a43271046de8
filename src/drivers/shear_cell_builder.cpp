#include "drivers/shear_cell_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>

#include "boundary/wall_monolayer.hpp"
#include "boundary/wall_owner.hpp"
#include "drivers/packing_growth.hpp"
#include "io/input_error.hpp"

namespace dilatant {

namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

void add_wall(World& world, const std::vector<WallSphere>& spheres, OwnerId wall, double density) {
  for (const WallSphere& s : spheres) {
    world.bodies.add_sphere(static_cast<std::int64_t>(world.bodies.size()), s.position, s.radius,
                            density, /*fixed=*/true);
    world.bodies.set_driven(world.bodies.size() - 1, wall);
  }
}

// Draws radii until the next one would overshoot cell.phi of Lx Ly
// counted_height, places them at random with centres in (z_lo, z_hi), grows
// them to full size around the bodies already there, and numbers them by
// height. Sets the geometry's mobile count and first index; returns the
// spheres' volume.
double add_mobile_spheres(const Config& config, double counted_height, double z_lo, double z_hi,
                          std::mt19937_64& rng, World& world, ShearCellGeometry& geometry) {
  const CellConfig& cell = *config.cell();
  const double lx = cell.size[0], ly = cell.size[1], lz = cell.size[2];
  const double target_volume = cell.phi * lx * ly * counted_height;
  std::uniform_real_distribution<double> ur(cell.radius_min, cell.radius_max);
  std::vector<double> radii;
  double volume = 0.0;
  for (;;) {
    const double r = ur(rng);
    if (volume + sphere_volume(r) > target_volume) break;
    radii.push_back(r);
    volume += sphere_volume(r);
  }
  if (radii.empty()) {
    throw InputError(fmt::format(
        "{}: cell.size = [{}, {}, {}] holds no mobile sphere at cell.phi = {} (radii up to "
        "{}); enlarge the cell",
        config.source, lx, ly, lz, cell.phi, cell.radius_max));
  }
  geometry.first_mobile = world.bodies.size();
  geometry.mobile_count = radii.size();
  std::uniform_real_distribution<double> ux(0.0, lx), uy(0.0, ly), uz(z_lo, z_hi);
  for (double r : radii) {
    // Sequenced draws (argument order is unspecified; g++ drew z, y, x).
    const double pz = uz(rng);
    const double py = uy(rng);
    const double px = ux(rng);
    world.bodies.add_sphere(static_cast<std::int64_t>(world.bodies.size()), Vec3(px, py, pz), r,
                            config.density, false);
  }

  // Start the growth where random positions overlap little (phi ~ 0.2).
  const double initial_scale = std::min(1.0, std::cbrt(0.2 / cell.phi));
  const GrowthReport growth = grow_to_full_size(world, geometry.first_mobile, initial_scale);
  geometry.growth_steps = growth.inflation_steps + growth.relaxation_steps;
  geometry.max_overlap = growth.max_overlap;
  if (growth.max_overlap > kPackingOverlapTolerance * cell.radius_min) {
    throw std::runtime_error(fmt::format(
        "could not pack cell.phi = {} without overlaps (largest overlap {:.3g} after {} "
        "relaxations); lower cell.phi",
        cell.phi, growth.max_overlap, growth.relaxation_steps));
  }
  // Number the mobile spheres from bottom to top: the parallel sweep works on
  // slabs in z (solver/slab_partition.hpp), and spheres of one slab then share
  // cache lines only with each other. Ids follow the new order.
  std::vector<std::size_t> by_height(geometry.mobile_count);
  std::iota(by_height.begin(), by_height.end(), geometry.first_mobile);
  std::stable_sort(by_height.begin(), by_height.end(), [&](std::size_t a, std::size_t b) {
    return world.bodies.position[a][2] < world.bodies.position[b][2];
  });
  world.bodies.reorder(geometry.first_mobile, by_height);
  for (std::size_t i = geometry.first_mobile; i < world.bodies.size(); ++i) {
    world.bodies.id[i] = static_cast<std::int64_t>(i);
  }
  return volume;
}

}  // namespace

World build_shear_cell(const Config& config, ShearCellGeometry& geometry, RoughWalls& walls) {
  const CellConfig& cell = *config.cell();
  const double lx = cell.size[0], ly = cell.size[1], lz = cell.size[2];
  std::mt19937_64 rng(static_cast<std::uint64_t>(cell.seed));

  World world;
  world.box.length = Vec3(lx, ly, lz);
  world.box.periodic = {true, true, false};
  world.planes.push_back(Plane{Vec3::Zero(), Vec3::UnitZ()});
  world.planes.push_back(Plane{Vec3(0.0, 0.0, lz), -Vec3::UnitZ()});

  const auto bottom = random_monolayer(lx, ly, 0.0, cell.radius_min, cell.radius_max, rng);
  const auto top = random_monolayer(lx, ly, lz, cell.radius_min, cell.radius_max, rng);
  add_wall(world, bottom, kBottomWall, config.density);
  add_wall(world, top, kTopWall, config.density);
  double wall_radius_sum = 0.0;
  for (const auto& s : bottom) wall_radius_sum += s.radius;
  for (const auto& s : top) wall_radius_sum += s.radius;
  geometry.wall_radius_mean = wall_radius_sum / double(bottom.size() + top.size());
  geometry.gap_height = lz - 2.0 * geometry.wall_radius_mean;

  // Mobile spheres: radii drawn until the next one would overshoot phi, counted
  // against the volume cell.phi_definition names.
  const double counted_height =
      cell.phi_definition == PhiDefinition::Box ? lz : geometry.gap_height;
  const double volume = add_mobile_spheres(config, counted_height, cell.radius_max,
                                           lz - cell.radius_max, rng, world, geometry);
  geometry.phi = volume / (lx * ly * geometry.gap_height);
  geometry.phi_box = volume / (lx * ly * lz);

  SlidingWall wall;
  double wall_mass = 0.0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    if (world.bodies.owner[i] != kTopWall) continue;
    wall.spheres.push_back(static_cast<std::int32_t>(i));
    wall_mass += config.density * sphere_volume(world.bodies.radius[i]);
  }
  wall.mass = cell.wall_mass > 0.0 ? cell.wall_mass : wall_mass;
  wall.drive_force = WallDrive::drive_force(drive_spec(config));
  // Start sheared: a linear profile has uniform stress, so the flow only has to
  // adjust its magnitude, which the whole gap does at once, instead of waiting
  // for momentum to diffuse from a wall that starts alone (several strain units
  // in the paper's cell).
  wall.velocity = cell.initial_shear_rate * lz;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    if (world.bodies.owner[i] == kTopWall) world.bodies.velocity[i] = Vec3(wall.velocity, 0, 0);
    if (world.bodies.is_driven(i)) continue;
    world.bodies.velocity[i] = Vec3(cell.initial_shear_rate * world.bodies.position[i][2], 0, 0);
  }
  walls = RoughWalls(std::move(wall), CoulombLaw{});
  return world;
}

DriveSpec drive_spec(const Config& config) {
  const CellConfig& cell = *config.cell();
  const bool images = cell.boundary == CellBoundary::LeesEdwards;
  return {.kind = images ? DriveKind::Images : DriveKind::Walls,
          .rate_controlled = cell.control != ShearControl::Stress,
          .pressure_controlled = cell.control == ShearControl::Pressure,
          .shear_stress = cell.shear_stress,
          .shear_rate = cell.shear_rate,
          .normal_stress = cell.normal_stress,
          .mass = images ? cell.boundary_mass : cell.wall_mass,
          .size = cell.size};
}

World build_cell(const Config& config, ShearCellGeometry& geometry, std::unique_ptr<Drive>& drive) {
  if (drive_spec(config).kind == DriveKind::Images) {
    ImageControl control;
    World world = build_lees_edwards_cell(config, geometry, control);
    drive = std::make_unique<ImageDrive>(control);
    return world;
  }
  RoughWalls walls;
  World world = build_shear_cell(config, geometry, walls);
  drive = std::make_unique<WallDrive>(std::move(walls), geometry.wall_gap());
  return world;
}

}  // namespace dilatant

namespace dilatant {

double top_wall_mass(const Config& config) {
  const CellConfig& cell = *config.cell();
  const double lx = cell.size[0], ly = cell.size[1], lz = cell.size[2];
  // The wall cell's draws, in its order (build_shear_cell): bottom, then top.
  std::mt19937_64 rng(static_cast<std::uint64_t>(cell.seed));
  random_monolayer(lx, ly, 0.0, cell.radius_min, cell.radius_max, rng);
  double mass = 0.0;
  for (const WallSphere& s : random_monolayer(lx, ly, lz, cell.radius_min, cell.radius_max, rng))
    mass += config.density * sphere_volume(s.radius);
  return mass;
}

World build_lees_edwards_cell(const Config& config, ShearCellGeometry& geometry,
                              ImageControl& control) {
  const CellConfig& cell = *config.cell();
  const double lx = cell.size[0], ly = cell.size[1], lz = cell.size[2];
  std::mt19937_64 rng(static_cast<std::uint64_t>(cell.seed));
  World world;
  world.box.length = Vec3(lx, ly, lz);
  world.box.periodic = {true, true, true};
  world.box.lees_edwards = true;  // at rest while the packing grows
  // phi is exact here: the mobile spheres' volume over Lx Ly Lz, no walls.
  const double volume = add_mobile_spheres(config, lz, 0.0, lz, rng, world, geometry);
  geometry.phi_box = volume / (lx * ly * lz);
  geometry.phi = geometry.phi_box;
  geometry.gap_height = lz;
  geometry.wall_radius_mean = 0.0;

  const bool rate = cell.control != ShearControl::Stress;  // rate or pressure
  control = ImageDrive::control_for(
      drive_spec(config), cell.boundary_mass > 0.0 ? cell.boundary_mass : top_wall_mass(config));
  // Start on the homogeneous profile, centred so that the box's momentum is
  // zero: u_x = gamma_dot (z - Lz/2), the images above at V = gamma_dot Lz
  // (under stress control gamma_dot = cell.initial_shear_rate, as the wall
  // cell starts; under rate control the imposed rate).
  const double gamma_dot = rate ? cell.shear_rate : cell.initial_shear_rate;
  world.box.shear_velocity = gamma_dot * lz;
  for (std::size_t i = 0; i < world.bodies.size(); ++i)
    world.bodies.velocity[i] = Vec3(gamma_dot * (world.bodies.position[i][2] - 0.5 * lz), 0, 0);
  return world;
}

}  // namespace dilatant
