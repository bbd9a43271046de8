#include "measure/bulk_fraction.hpp"

#include <algorithm>
#include <numbers>

namespace dilatant {

double slab_volume_fraction(const World& world, double z_lo, double z_hi) {
  const Bodies& b = world.bodies;
  double volume = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.is_driven(i)) continue;
    const double r = b.radius[i], z0 = b.position[i][2];
    const double lo = std::max(z_lo, z0 - r) - z0, hi = std::min(z_hi, z0 + r) - z0;
    if (hi <= lo) continue;
    auto F = [r](double u) { return std::numbers::pi * (r * r * u - u * u * u / 3.0); };
    volume += F(hi) - F(lo);
  }
  return volume / (world.box.length[0] * world.box.length[1] * (z_hi - z_lo));
}

}  // namespace dilatant
