#pragma once
// A drive as a checkpoint keeps it (drivers/shear_cell_state.cpp writes these
// fields in the places format 7 gives them, so that the files of earlier runs
// still resume): the union of both drives' state, the other drive's fields
// zero. The box's Lees–Edwards flag (world.box.lees_edwards), which the file
// keeps with the box, tells which drive the record holds.
//
// The bodies' owners (world/bodies.hpp) are the drive's business: with walls
// the record keeps one byte per body, the wall that owns it (wall_owner.hpp;
// format 7's "body groups", the same bytes), and restoring the drive gives
// the bodies their motion and owner back; without walls it keeps none.
#include <memory>
#include <vector>

#include "boundary/drive.hpp"
#include "boundary/image_drive.hpp"
#include "boundary/rough_walls.hpp"
#include "boundary/wall_drive.hpp"
#include "geometry/periodic_box.hpp"

namespace dilatant {

struct DriveRecord {
  std::vector<OwnerId> owners;  // of every body, the walls' (empty: no walls)
  SlidingWall wall;             // the top wall (WallDrive)
  ImageControl images;          // the images' control (ImageDrive)

  // What makes a record read from a damaged file one no run wrote, for a
  // world of `bodies` bodies in `box` (null: nothing): arrays that would be
  // read out of bounds, a driven mass that is not positive.
  const char* fault(const PeriodicBox& box, std::size_t bodies) const;
};

// The drive the record holds (the walls' contact law left at its default:
// a run setting, Drive::set_contact_law); gives `world`'s bodies, read from
// the same checkpoint, their motion and owner.
std::unique_ptr<Drive> restore_drive(DriveRecord record, World& world, WallGap gap);

}  // namespace dilatant
