#include "boundary/image_drive.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/drive_record.hpp"

namespace dilatant {

ImageControl ImageDrive::control_for(const DriveSpec& spec, double mass) {
  ImageControl c;
  c.area = spec.size[0] * spec.size[1];
  c.rate_controlled = spec.rate_controlled;
  c.rate = spec.rate_controlled ? spec.shear_rate : 0.0;
  c.drive_force = spec.shear_stress * c.area;
  c.mass = mass;
  return c;
}

// Under stress control the drive alone accelerates the images at tau A / M:
// from rest they move by a t^2 / 2 in a time t, no more than `reach` while
// t <= sqrt(2 reach / a), as the wall (wall_drive.cpp). Under rate control they
// do not accelerate; they move at V, and the bound is that of a body at V.
// The images are a box height Lz away; two bodies `span` apart in the
// homogeneous shear move relative to each other at the fraction span / Lz of
// the images' speed, and accelerate at that fraction of a.
double ImageDrive::time_step_bound(const World& world, double reach, double span) const {
  const double fraction = std::min(1.0, span / world.box.length[2]);
  const double a = control_.rate_controlled ? 0.0 : control_.drive_force / control_.mass;
  if (a > 0.0) return std::sqrt(2.0 * reach / (a * fraction));
  return reach / (std::abs(world.box.shear_velocity) * fraction);
}

void ImageDrive::respond(World& world, double sigma_zx, double dt) {
  PeriodicBox& box = world.box;
  if (control_.rate_controlled) {
    box.shear_velocity = control_.rate * box.length[2];
    return;
  }
  // M dV/dt = A (tau - sigma_zx), forward Euler over the step just taken
  // (image_drive.hpp): the force tau A drives the boundary, the flow's
  // stress across its plane, sigma_zx A, holds it back.
  box.shear_velocity += dt * (control_.drive_force - control_.area * sigma_zx) / control_.mass;
}

// The homogeneous shear of the box, centred at Lz/2 so that its momentum is zero.
ShearFlow ImageDrive::mean_flow(const World& world) const {
  return {.shear_rate = shear_rate(world), .z0 = 0.5 * world.box.length[2]};
}

BulkRegion ImageDrive::bulk_region(const World& world) const {
  const double lz = world.box.length[2];
  return {.z_lo = 0.0, .z_hi = lz, .flow_lo = 0.0, .flow_hi = lz, .whole_box = true};
}

// The images keep their offset and speed; the control is the spec's (a
// rate-controlled continuation imposes its rate from the first step), the mass
// the spec's if it names one. Lz must match: z is periodic.
bool ImageDrive::adopt(const DriveSpec& spec, World& world) {
  if (spec.kind != DriveKind::Images || world.box.length[2] != spec.size[2]) return false;
  control_ = control_for(spec, spec.mass > 0.0 ? spec.mass : control_.mass);
  if (control_.rate_controlled) world.box.shear_velocity = control_.rate * spec.size[2];
  return true;
}

DriveRecord ImageDrive::record(const World&) const {
  return {.owners = {}, .wall = {}, .images = control_};
}

}  // namespace dilatant
