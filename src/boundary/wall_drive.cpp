#include "boundary/wall_drive.hpp"

#include <cmath>

#include "boundary/drive_record.hpp"

namespace dilatant {

// From rest, the drive alone moves the wall by F t^2 / (2M) in a time t: no
// more than `reach` while t <= sqrt(2 reach M / F), past particles that have
// not moved yet, whatever the span.
double WallDrive::time_step_bound(const World&, double reach, double) const {
  const SlidingWall& wall = walls_.top();
  return std::sqrt(2.0 * reach * wall.mass / wall.drive_force);
}

// The profile a steady flow without slip has between the walls' mean
// surfaces (docs/shear-cell.md), at the wall's current speed: the fluid then
// neither drives nor brakes it.
ShearFlow WallDrive::mean_flow(const World&) const {
  return {.shear_rate = walls_.top().velocity / gap_.gap_height, .z0 = gap_.wall_radius_mean};
}

// The mean push of the particles on the two walls, (F_top,z - F_bottom,z) / 2
// over their area Lx Ly.
double WallDrive::normal_stress(const World& world, const WallForces& f, double) const {
  const double area = world.box.length[0] * world.box.length[1];
  return 0.5 * (f.top[2] - f.bottom[2]) / area;
}

BulkRegion WallDrive::bulk_region(const World& world) const {
  const double lz = world.box.length[2];
  // The central half of the gap, and the flow beyond one diameter (2 R) of the
  // walls' centres, which leaves out the first layer, stuck to the wall.
  return {.z_lo = 0.25 * lz, .z_hi = 0.75 * lz, .flow_lo = 2.0, .flow_hi = lz - 2.0};
}

// The walls stand where the state's cell put them: its Lz too must match.
bool WallDrive::adopt(const DriveSpec& spec, World& world) {
  if (spec.kind != DriveKind::Walls || world.box.length[2] != spec.size[2]) return false;
  SlidingWall& wall = walls_.top();
  wall.drive_force = drive_force(spec);
  if (spec.mass > 0.0) wall.mass = spec.mass;
  return true;
}

DriveRecord WallDrive::record(const World& world) const {
  return {.owners = world.bodies.owner, .wall = walls_.top(), .images = {}};
}

}  // namespace dilatant
