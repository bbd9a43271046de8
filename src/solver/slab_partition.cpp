#include "solver/slab_partition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dilatant {

SlabPartition SlabPartition::single(std::size_t contacts, std::size_t boundary_begin) {
  SlabPartition p;
  p.begin = {0, contacts};
  p.boundary_begin = {boundary_begin};
  return p;
}

namespace {

constexpr int kAxis = 2;  // z

bool touches_driven_body(const Bodies& b, const Contact& c) {
  return b.is_driven(static_cast<std::size_t>(c.i)) ||
         (!c.with_plane() && b.is_driven(static_cast<std::size_t>(c.other)));
}

double contact_point(const Contact& c, const Bodies& b) {
  return b.position[c.i][kAxis] - c.arm_i * c.normal[kAxis];
}

// Whether the slabs wrap around z: a Lees–Edwards box (z periodic, bounded by
// nothing).
bool cyclic_slabs(const World& world) {
  return world.box.periodic[kAxis] && world.box.lees_edwards;
}

// Extent of the contact points along the axis, and the largest distance along
// it from a contact point to the centre of one of its spheres.
struct Extent {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  double reach = 0.0;
};

Extent contact_extent(const std::vector<Contact>& contacts, const World& world) {
  const Bodies& b = world.bodies;
  Extent e;
  for (const Contact& c : contacts) {
    const double z = contact_point(c, b);
    e.low = std::min(e.low, z);
    e.high = std::max(e.high, z);
    e.reach = std::max(e.reach, std::abs(b.position[c.i][kAxis] - z));
    if (!c.with_plane()) {
      const Vec3 d = world.box.minimum_image(b.position[c.other], b.position[c.i]);
      e.reach = std::max(e.reach, std::abs(b.position[c.i][kAxis] + d[kAxis] - z));
    }
  }
  return e;
}

}  // namespace

SlabPartition partition_into_slabs(std::vector<Contact>& contacts, const World& world,
                                   std::vector<Contact>& scratch) {
  int slabs = 1;
  Extent e;
  const bool cyclic = cyclic_slabs(world);
  const double period = world.box.length[kAxis];
  if (cyclic && !contacts.empty()) {
    // Lees–Edwards: slabs cover the whole period [0, Lz), contact points
    // wrapped into it. The first and the last slab are neighbours through the
    // boundary; with an even count >= 4 they have different colours, and two
    // slabs of one colour are at least one slab apart around the cycle, so
    // the red-black argument holds as on a bounded axis (2 slabs would give
    // one slab per colour: no sharing, so at least 4).
    e = contact_extent(contacts, world);
    e.low = 0.0;
    e.high = period;
    for (int n = 4; n <= kMaxSlabs && std::isfinite(e.reach) && period / n >= 2.0 * e.reach; n *= 2)
      slabs = n;
  } else if (!world.box.periodic[kAxis] && !contacts.empty()) {
    // Bounded z. A periodic z without Lees–Edwards (a scene) keeps one slab,
    // as before the cyclic partition.
    e = contact_extent(contacts, world);
    const double length = e.high - e.low;
    // A flat (or non-finite) extent gives one slab: no width to cut.
    if (std::isfinite(length) && length > 0.0)
      while (2 * slabs <= kMaxSlabs && length / (2 * slabs) >= 2.0 * e.reach) slabs *= 2;
  }
  const double width = slabs > 1 ? (e.high - e.low) / slabs : 1.0;
  // Counting sort on key = 2 slab + touches_driven_body: stable, O(contacts).
  const auto key = [&](const Contact& c) {
    int slab = 0;
    if (slabs > 1) {
      // Clamped as a double first: a contact point outside the extent (or not
      // finite) must not overflow the cast.
      double z = contact_point(c, world.bodies);
      if (cyclic) z -= period * std::floor(z / period);
      const double at = (z - e.low) / width;
      slab = std::isfinite(at) ? static_cast<int>(std::clamp(at, 0.0, double(slabs - 1))) : 0;
    }
    return 2 * slab + (touches_driven_body(world.bodies, c) ? 1 : 0);
  };
  std::vector<std::size_t> first(2 * static_cast<std::size_t>(slabs) + 1, 0);
  for (const Contact& c : contacts) ++first[static_cast<std::size_t>(key(c)) + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  SlabPartition p;
  p.begin.resize(static_cast<std::size_t>(slabs) + 1);
  p.boundary_begin.resize(static_cast<std::size_t>(slabs));
  for (std::size_t s = 0; s < p.boundary_begin.size(); ++s) {
    p.begin[s] = first[2 * s];
    p.boundary_begin[s] = first[2 * s + 1];
  }
  p.begin.back() = contacts.size();
  scratch.resize(contacts.size());
  for (const Contact& c : contacts) scratch[first[static_cast<std::size_t>(key(c))]++] = c;
  contacts.swap(scratch);
  return p;
}

}  // namespace dilatant
