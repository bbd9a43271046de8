#pragma once
// Forces the contacts exert on the two walls during one step (impulse / dt).
#include <vector>

#include "boundary/wall_owner.hpp"
#include "detection/contact.hpp"

namespace dilatant {

struct WallForces {
  Vec3 bottom = Vec3::Zero();  // on the fixed wall (its spheres and the z = 0 plane)
  Vec3 top = Vec3::Zero();     // on the moving wall (its spheres and the z = Lz plane)
};

// A body counts for the wall that owns it (wall_owner.hpp); particles for none.
WallForces wall_forces(const Bodies& bodies, const std::vector<Contact>& contacts, double dt);

}  // namespace dilatant
