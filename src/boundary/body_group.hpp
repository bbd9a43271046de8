#pragma once
// Which part of a set-up each body belongs to: a mobile particle, or a sphere
// glued into one of the shear cell's rough walls. A boundary (boundary.hpp)
// names its bodies this way; measurements use it to leave the walls out.
#include <cstddef>
#include <cstdint>
#include <span>

namespace dilatant {

enum class BodyGroup : std::uint8_t { Particle = 0, BottomWall = 1, TopWall = 2 };

// True if body i belongs to a boundary; an empty list means no body does.
inline bool is_boundary_body(std::span<const BodyGroup> group, std::size_t i) {
  return !group.empty() && group[i] != BodyGroup::Particle;
}

}  // namespace dilatant
