#include "measure/sediment_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "measure/bulk_fraction.hpp"

namespace dilatant {

namespace {
constexpr double kSurfaceSlab = 0.5;  // slab thickness for phi(z), in largest radii
}

SedimentFraction sediment_fraction(const World& world, double radius_max, double exclusion) {
  const Bodies& b = world.bodies;
  SedimentFraction out;
  for (std::size_t i = 0; i < b.size(); ++i)
    out.top = std::max(out.top, b.position[i][2] + b.radius[i]);
  const double dz = kSurfaceSlab * radius_max;
  const int slabs = static_cast<int>(std::ceil(out.top / dz));
  if (slabs <= 0) return out;
  std::vector<double> profile(static_cast<std::size_t>(slabs));
  for (int k = 0; k < slabs; ++k)
    profile[std::size_t(k)] = slab_volume_fraction(world, k * dz, (k + 1) * dz);

  // Plateau: the interior, clear of the floor's layers and of the top's ragged
  // edge; the whole column if the sediment is too thin for that.
  const double lo = 4.0 * radius_max, hi = out.top - 8.0 * radius_max;
  double sum = 0.0;
  int count = 0;
  for (int k = 0; k < slabs; ++k) {
    const double z = (k + 0.5) * dz;
    if (z < lo || z > hi) continue;
    sum += profile[std::size_t(k)];
    ++count;
  }
  if (count == 0) {
    for (double p : profile) sum += p;
    count = slabs;
  }
  const double plateau = sum / count;
  out.surface = 0.0;
  for (int k = slabs - 1; k >= 0; --k) {
    if (profile[std::size_t(k)] >= 0.5 * plateau) {
      out.surface = (k + 1) * dz;
      break;
    }
  }
  const double z_lo = exclusion, z_hi = out.surface - exclusion;
  out.phi = z_hi > z_lo ? slab_volume_fraction(world, z_lo, z_hi) : 0.0;
  return out;
}

}  // namespace dilatant
