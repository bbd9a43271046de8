#pragma once
// Forces the contacts exert on the two walls during one step (impulse / dt).
#include <vector>

#include "solver/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

struct WallForces {
  Vec3 bottom = Vec3::Zero();  // on the fixed wall (its spheres and the z = 0 plane)
  Vec3 top = Vec3::Zero();     // on the moving wall (its spheres and the z = Lz plane)
};

WallForces wall_forces(const World& world, const std::vector<Contact>& contacts, double dt);

}  // namespace dilatant
