#include "world/bodies.hpp"

#include <algorithm>
#include <cstddef>
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
  motion.push_back(Motion::Dynamic);
  owner.push_back(kNoOwner);
}

std::ptrdiff_t Bodies::first_non_finite() const {
  for (std::size_t i = 0; i < size(); ++i) {
    if (!position[i].allFinite() || !velocity[i].allFinite() || !angular_velocity[i].allFinite())
      return static_cast<std::ptrdiff_t>(i);
  }
  return -1;
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

namespace {
template <class T>
void permute_tail(std::vector<T>& v, std::size_t first, const std::vector<std::size_t>& order) {
  std::vector<T> tail;
  tail.reserve(order.size());
  for (std::size_t i : order) tail.push_back(v[i]);
  std::copy(tail.begin(), tail.end(), v.begin() + static_cast<std::ptrdiff_t>(first));
}
}  // namespace

void Bodies::reorder(std::size_t first, const std::vector<std::size_t>& order) {
  permute_tail(position, first, order);
  permute_tail(velocity, first, order);
  permute_tail(angular_velocity, first, order);
  permute_tail(radius, first, order);
  permute_tail(inv_mass, first, order);
  permute_tail(inv_inertia, first, order);
  permute_tail(id, first, order);
  permute_tail(motion, first, order);
  permute_tail(owner, first, order);
}

}  // namespace dilatant
