#pragma once
// The owner ids the shear cell's rough walls give their glued spheres
// (world/bodies.hpp: a driven body's owner is the part of its boundary that
// moves it). Only boundary/ knows what the numbers mean. They are the bytes
// checkpoint format 7 keeps per body (drive_record.hpp) and the snapshots'
// `group` field (io/vtk_writer.hpp): 0 a particle, 1 the bottom wall, 2 the
// top wall.
#include "world/bodies.hpp"

namespace dilatant {

inline constexpr OwnerId kBottomWall = 1;
inline constexpr OwnerId kTopWall = 2;

}  // namespace dilatant
