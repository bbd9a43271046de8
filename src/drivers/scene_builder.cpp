#include "drivers/scene_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "detection/contact_detector.hpp"
#include "io/input_error.hpp"

namespace dilatant {

namespace {

void check_particles(const Config& config, const std::vector<ParticleRecord>& particles) {
  const auto file = config.scene()->particles.filename().string();
  for (const ParticleRecord& p : particles) {
    if (p.id < 0) {
      throw InputError(
          fmt::format("{}: particle id {}: ids must be >= 0 (negative ids name "
                      "planes in contacts.csv)",
                      file, p.id));
    }
    if (p.fixed && (p.velocity.norm() > 0.0 || p.angular_velocity.norm() > 0.0)) {
      throw InputError(
          fmt::format("{}: particle {}: a fixed particle must have zero velocity "
                      "and angular velocity",
                      file, p.id));
    }
  }
}

void check_box(const Config& config, const Bodies& b) {
  const SceneConfig& scene = *config.scene();
  double r_max = 0.0;
  for (double r : b.radius) r_max = std::max(r_max, r);
  for (int k = 0; k < 3; ++k) {
    if (scene.periodic[k] && scene.box[k] < 4.0 * r_max) {
      throw InputError(
          fmt::format("{}: scene.box[{}] = {}: a periodic axis must be at least 4 "
                      "largest radii ({}) long",
                      config.source, k, scene.box[k], 4.0 * r_max));
    }
  }
}

void check_overlaps(const Config& config, const World& world) {
  const Bodies& b = world.bodies;
  const double r_min = *std::min_element(b.radius.begin(), b.radius.end());
  const double tolerance = kOverlapTolerance * r_min;
  std::vector<Contact> contacts;
  ContactDetector detector;
  detector.detect(world, 0.0, contacts);
  const auto file = config.scene()->particles.filename().string();
  for (const Contact& c : contacts) {
    if (c.gap >= -tolerance) continue;
    if (c.with_plane()) {
      throw InputError(
          fmt::format("{}: particle {} penetrates scene.planes[{}] by {:.3g} "
                      "(tolerance {:.3g})",
                      file, b.id[c.i], c.plane_index(), -c.gap, tolerance));
    }
    throw InputError(fmt::format("{}: particles {} and {} overlap by {:.3g} (tolerance {:.3g})",
                                 file, b.id[c.i], b.id[c.other], -c.gap, tolerance));
  }
  // The detector skips fixed-fixed pairs and fixed spheres against planes: glued
  // bodies may touch each other, they never move.
}

}  // namespace

World build_scene_world(const Config& config, const std::vector<ParticleRecord>& particles) {
  const SceneConfig& scene = *config.scene();
  check_particles(config, particles);
  World world;
  world.gravity = scene.gravity;
  world.box.length = scene.box;
  world.box.periodic = scene.periodic;
  for (const PlaneConfig& p : scene.planes)
    world.planes.push_back(Plane{p.point, p.normal.normalized()});
  for (const ParticleRecord& p : particles) {
    world.bodies.add_sphere(p.id, p.position, p.radius, config.density, p.fixed, p.velocity,
                            p.angular_velocity);
  }
  check_box(config, world.bodies);
  for (Vec3& x : world.bodies.position) x = world.box.wrap(x);
  check_overlaps(config, world);
  return world;
}

double automatic_time_step(const World& world, const Config& config) {
  const Bodies& b = world.bodies;
  const double r_min = *std::min_element(b.radius.begin(), b.radius.end());
  double v_max = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    v_max = std::max(v_max, b.velocity[i].norm() + b.radius[i] * b.angular_velocity[i].norm());
  }
  const double g = world.gravity.norm();
  double t = std::numeric_limits<double>::infinity();
  if (g > 0.0) t = std::min(t, std::sqrt(r_min / g));
  if (v_max > 0.0) t = std::min(t, r_min / v_max);
  if (!std::isfinite(t)) {
    throw InputError(
        fmt::format("{}: solver.dt = 0 (automatic) needs gravity or initial "
                    "velocities to set a time scale; give solver.dt",
                    config.source));
  }
  return std::min(0.01 * t, config.scene()->trajectory_interval);
}

}  // namespace dilatant
