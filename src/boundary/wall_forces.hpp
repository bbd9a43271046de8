#pragma once
// Forces the contacts exert on the two walls during one step (impulse / dt).
#include <vector>

#include "boundary/body_group.hpp"
#include "detection/contact.hpp"

namespace dilatant {

struct WallForces {
  Vec3 bottom = Vec3::Zero();  // on the fixed wall (its spheres and the z = 0 plane)
  Vec3 top = Vec3::Zero();     // on the moving wall (its spheres and the z = Lz plane)
};

// `group` is the walls' Boundary::body_groups().
WallForces wall_forces(std::span<const BodyGroup> group, const std::vector<Contact>& contacts,
                       double dt);

}  // namespace dilatant
