#include "world/bodies.hpp"

#include <numbers>

namespace dilatant {

void Bodies::add_sphere(std::int64_t user_id, const Vec3& x, double r, double density, bool fixed,
                        const Vec3& v, const Vec3& w) {
  const double m = 4.0 / 3.0 * std::numbers::pi * density * r * r * r;
  position.push_back(x);
  velocity.push_back(fixed ? Vec3::Zero() : v);
  angular_velocity.push_back(fixed ? Vec3::Zero() : w);
  radius.push_back(r);
  inv_mass.push_back(fixed ? 0.0 : 1.0 / m);
  inv_inertia.push_back(fixed ? 0.0 : 1.0 / (0.4 * m * r * r));
  id.push_back(user_id);
}

double Bodies::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < size(); ++i) {
    if (inv_mass[i] == 0.0) continue;
    e += 0.5 * velocity[i].squaredNorm() / inv_mass[i] +
         0.5 * angular_velocity[i].squaredNorm() / inv_inertia[i];
  }
  return e;
}

Vec3 Bodies::momentum() const {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < size(); ++i) {
    if (inv_mass[i] > 0.0) p += velocity[i] / inv_mass[i];
  }
  return p;
}

}  // namespace dilatant
