#pragma once
// Dense initial packings by growth: random insertion alone stalls near phi 0.38,
// so mobile spheres start at random positions with shrunken radii and are
// inflated step by step to their final radii. After each inflation, overlaps
// are removed by one frictionless Contact Dynamics projection: with all
// velocities zero and dt = 1, the solver finds the smallest mass-weighted
// displacements that make every gap non-negative (the Signorini condition
// g + dt u_n >= 0 of the time step), which are then applied and forgotten.
// Fixed bodies (walls) and planes take part as immovable obstacles.
#include <cstddef>

#include "world/world.hpp"

namespace dilatant {

// Overlap a finished packing may keep, relative to the smallest radius.
inline constexpr double kPackingOverlapTolerance = 1e-6;

struct GrowthReport {
  int inflation_steps = 0;
  int relaxation_steps = 0;
  double max_overlap = 0.0;  // after the last relaxation, in units of length
};

// Grows bodies [first, end) from `initial_scale` x their radius to full size.
// Radii in `world` must be the final ones; masses are left untouched. Driven
// bodies (a cell's walls, world/bodies.hpp) stay where they are.
GrowthReport grow_to_full_size(World& world, std::size_t first, double initial_scale);

}  // namespace dilatant
