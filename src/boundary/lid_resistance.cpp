#include "boundary/lid_resistance.hpp"

namespace dilatant {

double film_lid_resistance(const std::vector<Contact>& contacts, double volume, double height,
                           double dt) {
  double sum = 0.0;
  for (const Contact& c : contacts) {
    if (c.with_plane() || c.lubrication <= 0.0) continue;
    // d_z n_z = |d| n_z^2, the branch rebuilt from the record (particle_stress.cpp).
    const double nz = c.normal[2];
    const double dz_nz = (c.arm_i + c.arm_j + c.gap) * nz * nz;
    sum += c.lubrication * dz_nz * dz_nz;
  }
  return sum / (dt * volume * height);
}

}  // namespace dilatant
