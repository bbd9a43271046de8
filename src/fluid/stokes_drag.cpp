#include "fluid/stokes_drag.hpp"

#include <numbers>

namespace dilatant {

void StokesDrag::assign(const World& world, const ShearFlow& flow, BodyDrag& drag) const {
  const Bodies& b = world.bodies;
  const std::size_t n = b.size();
  constexpr double pi = std::numbers::pi;
  drag.translational.resize(n);
  drag.rotational.resize(n);
  const bool sheared = flow.shear_rate != 0.0;
  drag.fluid_velocity.resize(sheared ? n : 0);
  drag.fluid_spin.assign(sheared ? n : 0, Vec3(0.0, 0.5 * flow.shear_rate, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    const double r = b.radius[i];
    drag.translational[i] = 6.0 * pi * eta_f * r;
    drag.rotational[i] = 8.0 * pi * eta_f * r * r * r;
    if (sheared)
      drag.fluid_velocity[i] = Vec3(flow.shear_rate * (b.position[i].z() - flow.z0), 0.0, 0.0);
  }
}

}  // namespace dilatant
