#include "boundary/rough_walls.hpp"

namespace dilatant {

void RoughWalls::predict(Bodies& bodies, double dt) {
  // Work of the drive over the prediction, F dt (V + V_free)/2: exactly the
  // wall's kinetic-energy gain before the contacts act.
  drive_work_ = top_.drive_force * dt * (top_.velocity + 0.5 * dt * top_.drive_force / top_.mass);
  free_velocity_ = top_.velocity + dt * top_.drive_force / top_.mass;
  for (std::int32_t s : top_.spheres) bodies.velocity[s] = Vec3(free_velocity_, 0.0, 0.0);
}

void RoughWalls::begin_solve(const std::vector<Contact>& contacts, const Bodies& bodies) {
  // Before the passes' threads start: afterwards solve_block() writes only V.
  block_ = {.velocity = top_.velocity, .inv_mass = 1.0 / top_.mass, .owner = kTopWall};
  top_contacts_.clear();
  const std::vector<OwnerId>& owner = bodies.owner;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& c = contacts[k];
    const auto index = static_cast<std::int32_t>(k);
    if (owner[c.i] == kTopWall) top_contacts_.emplace_back(index, 1.0);
    if (!c.with_plane() && owner[c.other] == kTopWall) {
      top_contacts_.emplace_back(index, -1.0);
    }
  }
}

void RoughWalls::solve_block(const std::vector<Contact>& contacts, Bodies& bodies) {
  double impulse_x = 0.0;
  for (const auto& [index, sign] : top_contacts_) {
    const Contact& c = contacts[index];
    impulse_x += sign * ((c.p_n + c.p_lub) * c.normal[0] + c.p_t[0]);
  }
  top_.velocity = free_velocity_ + impulse_x / top_.mass;
  block_.velocity = top_.velocity;
  for (std::int32_t s : top_.spheres) bodies.velocity[s] = Vec3(top_.velocity, 0.0, 0.0);
}

}  // namespace dilatant
