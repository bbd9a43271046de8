#pragma once
// The simulation box: lengths and which axes wrap around.
// Non-periodic axes are unbounded (walls and planes confine the particles there).
#include <array>
#include <cmath>

#include "geometry/vec3.hpp"

namespace dilatant {

struct PeriodicBox {
  Vec3 length = Vec3::Zero();
  std::array<bool, 3> periodic = {false, false, false};

  // Shortest vector from b to a, taking the nearest periodic image of b.
  Vec3 minimum_image(const Vec3& a, const Vec3& b) const {
    Vec3 d = a - b;
    for (int k = 0; k < 3; ++k) {
      if (periodic[k]) d[k] -= length[k] * std::round(d[k] / length[k]);
    }
    return d;
  }

  // Maps a position back into [0, L) along every periodic axis.
  Vec3 wrap(Vec3 x) const {
    for (int k = 0; k < 3; ++k) {
      if (periodic[k]) x[k] -= length[k] * std::floor(x[k] / length[k]);
    }
    return x;
  }
};

}  // namespace dilatant
