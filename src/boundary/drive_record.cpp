#include "boundary/drive_record.hpp"

#include "friction/coulomb_law.hpp"

namespace dilatant {

const char* DriveRecord::fault(const PeriodicBox& box, std::size_t bodies) const {
  if (!owners.empty() && owners.size() != bodies) return "body groups";
  for (const std::int32_t i : wall.spheres)
    if (i < 0 || static_cast<std::size_t>(i) >= bodies) return "wall sphere index";
  const bool needs_mass = !images.rate_controlled || images.pressure_controlled;
  const bool mass_missing = box.lees_edwards ? needs_mass && !(images.mass > 0.0)
                                             : !wall.spheres.empty() && !(wall.mass > 0.0);
  return mass_missing ? "boundary mass" : nullptr;
}

std::unique_ptr<Drive> restore_drive(DriveRecord record, World& world, WallGap gap) {
  Bodies& b = world.bodies;
  b.motion.assign(b.size(), Motion::Dynamic);
  b.owner.assign(b.size(), kNoOwner);
  // A wall's sphere is driven (the bottom one at rest, the top one by V).
  for (std::size_t i = 0; i < record.owners.size(); ++i)
    if (record.owners[i] != kNoOwner) b.set_driven(i, record.owners[i]);
  if (world.box.lees_edwards) {
    // The box's dilation rate is the lid's W / H (image_drive.hpp): the
    // checkpoint keeps W, the contacts of the next step read W / H.
    const ImageControl& c = record.images;
    world.box.dilation_rate = c.pressure_controlled ? c.height_speed / world.box.length[2] : 0.0;
    return std::make_unique<ImageDrive>(record.images);
  }
  return std::make_unique<WallDrive>(RoughWalls(std::move(record.wall), CoulombLaw{}), gap);
}

}  // namespace dilatant
