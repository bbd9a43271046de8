#include "boundary/drive_record.hpp"

#include "friction/coulomb_law.hpp"

namespace dilatant {

const char* DriveRecord::fault(const PeriodicBox& box, std::size_t bodies) const {
  if (!groups.empty() && groups.size() != bodies) return "body groups";
  for (const std::int32_t i : wall.spheres)
    if (i < 0 || static_cast<std::size_t>(i) >= bodies) return "wall sphere index";
  const bool mass_missing = box.lees_edwards ? !images.rate_controlled && !(images.mass > 0.0)
                                             : !wall.spheres.empty() && !(wall.mass > 0.0);
  return mass_missing ? "boundary mass" : nullptr;
}

std::unique_ptr<Drive> restore_drive(DriveRecord record, const PeriodicBox& box, WallGap gap) {
  if (box.lees_edwards) return std::make_unique<ImageDrive>(record.images);
  return std::make_unique<WallDrive>(
      RoughWalls(std::move(record.groups), std::move(record.wall), CoulombLaw{}), gap);
}

}  // namespace dilatant
