#pragma once
// Everything the time stepper advances: bodies, fixed planes, the box, and the
// external fields acting on them.
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/periodic_box.hpp"
#include "world/bodies.hpp"
#include "world/plane.hpp"
#include "world/sliding_wall.hpp"

namespace dilatant {

// Which part of a set-up a sphere belongs to (shear cell walls are glued spheres).
enum class BodyGroup : std::uint8_t { Particle = 0, BottomWall = 1, TopWall = 2 };

struct World {
  Bodies bodies;
  std::vector<BodyGroup> group;  // per body; empty means all are particles
  std::vector<Plane> planes;
  PeriodicBox box;
  Vec3 gravity = Vec3::Zero();
  // Extra constant force on each body (e.g. a driving force); empty means none.
  std::vector<Vec3> external_force;
  std::optional<SlidingWall> sliding_wall;
  double time = 0.0;

  bool is_wall(std::size_t i) const { return !group.empty() && group[i] != BodyGroup::Particle; }
};

}  // namespace dilatant
