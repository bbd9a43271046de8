#pragma once
// Red-black slabs along z: the order of a Gauss–Seidel pass that two or more
// threads can share without locks, and with results that do not depend on the
// number of threads.
//
// Each contact belongs to the slab holding its contact point. The slabs are at
// least twice as wide as the farthest a contact's sphere centre lies from its
// contact point, so contacts of two slabs that are not neighbours never share
// a sphere that moves (fixed bodies, inv_mass = 0, are never written). A pass
// therefore solves all even slabs side by side, then all odd ones; inside a
// slab contacts keep their (i, j) order, those touching a driven body
// (world/bodies.hpp) after the others: they obey the boundary's law, one
// dispatch per range. The order is fixed by the geometry and the bodies'
// motion types alone, so 1, 2 or 4 threads compute bit-identical impulses.
//
// Why z: in the shear cell spheres move along x and only diffuse in z, so
// spheres numbered by height at the start (drivers/shear_cell_builder.cpp) stay
// grouped in memory by slab, and two threads rarely write to one cache line.
// The slab count is 1, 2, 4 or 8 (8 keeps the even and odd halves balanced on
// 2 and 4 threads), the largest that fits; one slab if z is periodic, except
// in a Lees–Edwards box, where 4 or 8 slabs wrap around the period (an even
// count: the first and last slabs, neighbours through the boundary, have
// different colours; slab_partition.cpp).
#include <cstddef>
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

struct SlabPartition {
  // Slab k holds contacts [begin[k], boundary_begin[k]) between dynamic bodies
  // (or a dynamic body and a plane) and [boundary_begin[k], begin[k + 1])
  // touching a driven body (world/bodies.hpp; they obey the boundary's contact
  // law). begin has count() + 1 entries.
  std::vector<std::size_t> begin{0, 0};
  std::vector<std::size_t> boundary_begin{0};

  int count() const { return static_cast<int>(boundary_begin.size()); }
  static SlabPartition single(std::size_t contacts, std::size_t boundary_begin);
};

inline constexpr int kMaxSlabs = 8;

// Reorders `contacts` by slab (keeping their relative order inside a slab) and
// returns the ranges, reading which bodies are driven from world.bodies;
// `scratch` is reused storage.
SlabPartition partition_into_slabs(std::vector<Contact>& contacts, const World& world,
                                   std::vector<Contact>& scratch);

}  // namespace dilatant
