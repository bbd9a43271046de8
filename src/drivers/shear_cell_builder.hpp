#pragma once
// The paper's shear cell (docs/model.md "The shear cell"; Fernandez et al. 2013, p. 2): mobile
// spheres between a fixed rough bottom wall and a rough top wall that slides along x under a
// constant force, periodic in x and y, at constant volume.
//
//     z = Lz  ooooooooooooooooo  top wall: glued spheres, one rigid body, moves in x
//              .  o  . o  .  o
//              o  .  o  .  o       mobile spheres, phi between the walls' surfaces
//              .  o  .  o  .
//     z = 0   ooooooooooooooooo  bottom wall: glued spheres, fixed
//
// Safety planes at z = 0 and z = Lz (facing inwards) keep a sphere from
// slipping through a hole between glued wall spheres.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "boundary/drive.hpp"
#include "boundary/image_drive.hpp"
#include "boundary/rough_walls.hpp"
#include "boundary/wall_drive.hpp"
#include "io/config.hpp"
#include "world/world.hpp"

namespace dilatant {

struct ShearCellGeometry {
  std::size_t mobile_count = 0;
  std::size_t first_mobile = 0;  // bodies [first_mobile, end) are mobile
  double wall_radius_mean = 0.0;
  double phi = 0.0;               // V_mobile / (Lx Ly (Lz - 2 r_w)), as realised
  double phi_box = 0.0;           // V_mobile / (Lx Ly Lz)
  double gap_height = 0.0;        // Lz - 2 r_w, between the walls' mean surfaces
  std::int64_t growth_steps = 0;  // 64-bit: no padding in the checkpoint's raw bytes
  double max_overlap = 0.0;

  WallGap wall_gap() const {
    return {.wall_radius_mean = wall_radius_mean, .gap_height = gap_height};
  }
};

// What config's [cell] asks of the drive (boundary/drive.hpp).
DriveSpec drive_spec(const Config& config);

// The cell config.cell()->boundary names, with its drive: the rough walls or the
// Lees–Edwards images (below). The one place a cell's kind is chosen; the
// cell asks its drive, never the kind (drivers/shear_cell.cpp).
World build_cell(const Config& config, ShearCellGeometry& geometry, std::unique_ptr<Drive>& drive);

// Builds the walls and a packing of mobile spheres at config.cell()->phi,
// reproducibly from cell.seed: the world (walls' spheres first, then the mobile
// ones numbered by height) and its boundary, the rough walls. The walls'
// contact law is left at its default: it depends on eta_f, a run setting.
World build_shear_cell(const Config& config, ShearCellGeometry& geometry, RoughWalls& walls);

// The wall-free cell (cell.boundary = "lees-edwards"; boundary/image_drive.hpp):
// a triply periodic box of mobile spheres at cell.phi of Lx Ly Lz exactly,
// grown as the wall cell's packing, with Lees–Edwards images and their
// control; bodies on the centred linear profile. Geometry: phi = phi_box,
// gap_height = Lz, no walls.
World build_lees_edwards_cell(const Config& config, ShearCellGeometry& geometry,
                              ImageControl& control);

// The mass of the wall cell's top wall for this cell.size and cell.seed (the
// default fictitious mass of the Lees–Edwards boundary).
double top_wall_mass(const Config& config);

}  // namespace dilatant
