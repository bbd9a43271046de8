#include "boundary/wall_monolayer.hpp"

#include <cmath>

namespace dilatant {

std::vector<WallSphere> random_monolayer(double lx, double ly, double z0, double radius_min,
                                         double radius_max, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ux(0.0, lx), uy(0.0, ly), ur(radius_min, radius_max);
  std::vector<WallSphere> wall;
  // A plain O(N) scan per attempt: a wall holds ~100 discs, so this costs
  // milliseconds and keeps the adsorption rule obvious.
  for (int failures = 0; failures < kSaturationAttempts;) {
    // Sequenced draws: the order of function arguments is unspecified (g++
    // drew y first, clang x). y first keeps the configurations seeds gave.
    const double py = uy(rng);
    const double px = ux(rng);
    const Vec3 x(px, py, z0);
    const double r = ur(rng);
    bool free = true;
    for (const WallSphere& s : wall) {
      double dx = x[0] - s.position[0], dy = x[1] - s.position[1];
      dx -= lx * std::round(dx / lx);
      dy -= ly * std::round(dy / ly);
      const double d = r + s.radius;
      if (dx * dx + dy * dy < d * d) {
        free = false;
        break;
      }
    }
    if (free) {
      wall.push_back({x, r});
      failures = 0;
    } else {
      ++failures;
    }
  }
  return wall;
}

}  // namespace dilatant
