#pragma once
// The volume fraction of a sediment resting on a floor at z = 0, away from the
// floor's layering and from the loose free surface.
//
// The free surface is located from the packing itself: the horizontally
// averaged volume fraction phi(z), in slabs of `kSurfaceSlab` (0.5 largest
// radii), is averaged over its interior (from 2 diameters above the floor to 4
// diameters below the highest sphere top) to a plateau phi_p; the surface z_s
// is the highest slab top where phi(z) still reaches phi_p / 2 (the height at
// which the packing has thinned to half its density, a Gibbs-like dividing
// surface). The bulk fraction is the exact fraction of the slab
// [exclusion, z_s - exclusion] (measure/bulk_fraction.hpp); `exclusion` is in
// the same units as the positions (a choice shown with its sensitivity in
// docs/jamming.md).
#include "world/world.hpp"

namespace dilatant {

struct SedimentFraction {
  double surface = 0.0;  // z_s
  double phi = 0.0;      // between exclusion and z_s - exclusion; 0 if that is empty
  double top = 0.0;      // highest sphere top
};

// `radius_max` scales the slabs and the interior; `exclusion` is measured from
// the floor and from the surface. Every body of `world` counts (a sediment has
// no driven bodies).
SedimentFraction sediment_fraction(const World& world, double radius_max, double exclusion);

}  // namespace dilatant
