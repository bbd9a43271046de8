#pragma once
// All spheres of a simulation, stored as contiguous arrays (structure of arrays):
// the solver's hot loop touches only velocities and inverse masses, so keeping
// them apart from positions and bookkeeping keeps the loop in cache.
//
// Every body has a motion type and an owner, as a body in Jolt Physics has a
// motion type: the solver and the measurements ask what a body does, never
// which part of which set-up it is.
//
//   Dynamic  moved by the contact problem (a particle);
//   Driven   moved by a boundary (boundary/boundary.hpp), which imposes or
//            integrates its velocity itself: it has infinite mass in the
//            contact problems (inv_mass 0), its contacts obey the boundary's
//            law and come last in their slab (solver/slab_partition.hpp), and
//            measurements of the flow leave it out.
//
// The owner says which part of a boundary a body belongs to, as that boundary
// numbers its parts (boundary/wall_owner.hpp: the shear cell's bottom and top
// walls); kNoOwner for a body that belongs to none. Both are bookkeeping: the
// hot loop never reads them.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

enum class Motion : std::uint8_t { Dynamic = 0, Driven = 1 };
using OwnerId = std::uint8_t;
inline constexpr OwnerId kNoOwner = 0;

struct Bodies {
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> angular_velocity;
  std::vector<double> radius;
  std::vector<double> inv_mass;     // 0 for a fixed body
  std::vector<double> inv_inertia;  // 1/(2/5 m r^2); 0 for a fixed body
  std::vector<std::int64_t> id;     // user-facing identifier (from the input file)
  std::vector<Motion> motion;       // Dynamic unless a boundary drives the body
  std::vector<OwnerId> owner;       // kNoOwner unless a boundary owns the body

  std::size_t size() const { return position.size(); }
  bool is_fixed(std::size_t i) const { return inv_mass[i] == 0.0; }
  bool is_driven(std::size_t i) const { return motion[i] == Motion::Driven; }
  // Hands body i to part `part` of a boundary, which drives it from now on.
  void set_driven(std::size_t i, OwnerId part) {
    motion[i] = Motion::Driven;
    owner[i] = part;
  }

  // Adds a solid sphere of uniform density; a fixed sphere has infinite mass.
  // It is dynamic and has no owner until set_driven().
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
