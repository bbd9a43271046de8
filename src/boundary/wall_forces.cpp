#include "boundary/wall_forces.hpp"

namespace dilatant {

WallForces wall_forces(const Bodies& bodies, const std::vector<Contact>& contacts, double dt) {
  const std::vector<OwnerId>& owner = bodies.owner;
  WallForces f;
  auto add = [&](OwnerId wall, const Vec3& force) {
    if (wall == kBottomWall) f.bottom += force;
    if (wall == kTopWall) f.top += force;
  };
  for (const Contact& c : contacts) {
    if (c.p_n <= 0.0 && c.p_lub == 0.0) continue;
    // Contact and squeeze film alike: the wall feels every force of the pair.
    const Vec3 on_i = ((c.p_n + c.p_lub) * c.normal + c.p_t) / dt;
    add(owner[c.i], on_i);
    if (c.with_plane()) {
      // Safety plane 0 is the bottom wall's, plane 1 the top wall's.
      add(c.plane_index() == 0 ? kBottomWall : kTopWall, -on_i);
    } else {
      add(owner[c.other], -on_i);
    }
  }
  return f;
}

}  // namespace dilatant
