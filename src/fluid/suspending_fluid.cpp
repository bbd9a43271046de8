#include "fluid/suspending_fluid.hpp"

#include <algorithm>

namespace dilatant {

void SuspendingFluid::body_drag(const World& world, BodyDrag& drag) const {
  if (drag_) drag_->assign(world, flow_, drag);
}

double SuspendingFluid::pair_range(const World& world) const {
  if (!film_) return 0.0;
  double r_max = 0.0;
  for (const double r : world.bodies.radius) r_max = std::max(r_max, r);
  return film_->range(r_max);
}

void SuspendingFluid::pair_resistance(std::vector<Contact>& contacts, double dt) const {
  if (film_) film_->assign(contacts, dt);
}

}  // namespace dilatant
