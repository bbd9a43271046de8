#pragma once
// An infinite, fixed, flat wall. Particles live on the side the normal points to.
#include "geometry/vec3.hpp"

namespace dilatant {

struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit length (normalised by the builder)

  // Signed distance of x from the plane, positive on the particles' side.
  double distance(const Vec3& x) const { return (x - point).dot(normal); }
};

}  // namespace dilatant
