#pragma once
// Volume fraction of the dynamic bodies inside a horizontal slab z_lo < z < z_hi
// of the periodic Lx x Ly cell: each sphere contributes exactly the part of its
// volume inside the slab,
//     V = [F(z)] from max(z_lo, z0 - r) to min(z_hi, z0 + r),
//     F(z) = pi (r^2 (z - z0) - (z - z0)^3 / 3).
// In the central region it measures phi_bulk, free of the layering at the
// cell's edges.
#include "world/world.hpp"

namespace dilatant {

// A boundary's driven bodies (world/bodies.hpp) are left out.
double slab_volume_fraction(const World& world, double z_lo, double z_hi);

}  // namespace dilatant
