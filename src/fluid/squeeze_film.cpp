#include "fluid/squeeze_film.hpp"

#include <algorithm>
#include <numbers>

namespace dilatant {

double SqueezeFilm::resistance(double gap, double r_i, double r_j) const {
  const bool plane = r_j <= 0.0;
  const double mean_radius = plane ? r_i : 0.5 * (r_i + r_j);
  if (gap >= cutoff * mean_radius) return 0.0;
  const double a = plane ? r_i : r_i * r_j / (r_i + r_j);  // a*
  return 6.0 * std::numbers::pi * eta_f * a * a /
         (std::max(gap, 0.0) + regularization * mean_radius);
}

void SqueezeFilm::assign(std::vector<Contact>& contacts, double dt) const {
  for (Contact& c : contacts) {
    c.lubrication = dt * resistance(c.gap, c.arm_i, c.with_plane() ? 0.0 : c.arm_j);
  }
}

}  // namespace dilatant
