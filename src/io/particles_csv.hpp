#pragma once
// Particles of a scene, read from CSV (README "Scene configuration").
//
// One header row naming the columns, in any order:
//   id,x,y,z,r                required: integer id, centre, radius (> 0)
//   vx,vy,vz                  optional: velocity, default 0
//   wx,wy,wz                  optional: angular velocity, default 0
//   fixed                     optional: 0/1/true/false; a fixed particle never moves
// then one row per particle. Units are the scene's. Blank lines are skipped,
// fields are trimmed, CRLF line ends are accepted. Unknown or duplicate columns,
// malformed or non-finite numbers, radii <= 0, duplicate ids and a file without
// particles are errors: InputError "file:line: ...".
#include <cstdint>
#include <filesystem>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

struct ParticleRecord {
  std::int64_t id = 0;
  Vec3 position = Vec3::Zero();
  double radius = 0.0;
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  bool fixed = false;
};

// The particles in file order.
std::vector<ParticleRecord> read_particles_csv(const std::filesystem::path& file);

}  // namespace dilatant
