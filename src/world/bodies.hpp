#pragma once
// All spheres of a simulation, stored as contiguous arrays (structure of arrays):
// the solver's hot loop touches only velocities and inverse masses, so keeping
// them apart from positions and bookkeeping keeps the loop in cache.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

struct Bodies {
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> angular_velocity;
  std::vector<double> radius;
  std::vector<double> inv_mass;     // 0 for a fixed body
  std::vector<double> inv_inertia;  // 1/(2/5 m r^2); 0 for a fixed body
  std::vector<std::int64_t> id;     // user-facing identifier (from the input file)

  std::size_t size() const { return position.size(); }
  bool is_fixed(std::size_t i) const { return inv_mass[i] == 0.0; }

  // Adds a solid sphere of uniform density; a fixed sphere has infinite mass.
  void add_sphere(std::int64_t user_id, const Vec3& x, double r, double density, bool fixed,
                  const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero());

  double mass(std::size_t i) const { return inv_mass[i] > 0.0 ? 1.0 / inv_mass[i] : 0.0; }
  double kinetic_energy() const;
  // Index of the first body with a non-finite position, velocity or spin, or -1:
  // a state that has blown up (drivers stop on it, never write it as a result).
  std::ptrdiff_t first_non_finite() const;
  Vec3 momentum() const;

  // Puts body order[k] at index first + k (order is a permutation of
  // first .. size()-1), keeping ids with their bodies.
  void reorder(std::size_t first, const std::vector<std::size_t>& order);
};

}  // namespace dilatant
