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
  c.pressure_controlled = spec.pressure_controlled;
  c.normal_force = spec.pressure_controlled ? spec.normal_stress * c.area : 0.0;
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
  const double by_speed = reach / (std::abs(world.box.shear_velocity) * fraction);
  if (!control_.pressure_controlled) return by_speed;
  // The height, as the boundary under stress control: the lid (the top of the
  // box) accelerates at no more than P A / M from rest, or moves at W; a body
  // `span` above another moves the fraction span / Lz of that relative to it.
  const double a_h = control_.normal_force / control_.mass;
  const double by_push = std::sqrt(2.0 * reach / (a_h * fraction));
  const double w = std::abs(control_.height_speed);
  const double by_height = w > 0.0 ? reach / (w * fraction) : by_push;
  return std::min({by_speed, by_push, by_height});
}

void ImageDrive::dilate(World& world, double s) const {
  for (Vec3& x : world.bodies.position) x[2] *= s;
  world.box.length[2] *= s;
  if (control_.rate_controlled) world.box.shear_velocity = control_.rate * world.box.length[2];
}

void ImageDrive::respond(World& world, const StepStress& stress, double dt) {
  PeriodicBox& box = world.box;
  if (control_.pressure_controlled) {
    // First the dilation the step's contacts saw (Contact::dilation_drift,
    // eps_dot = W / H): H -> H + W dt, so that the gaps the solve predicted are
    // the gaps the bodies end with. A step that would fold the box (s <= 0,
    // only from a state far from the automatic step's bound) halves it
    // instead: the height stays positive.
    const double h = box.length[2];
    dilate(world, std::max(0.5, (h + control_.height_speed * dt) / h));
    // Then M dW/dt = A (p - P), linearly implicit in the films' response
    // p(W) = p_n - c (W - W_n) (boundary/lid_resistance.hpp):
    //   W += dt A (p_n - P) / (M + dt A c)     (image_drive.hpp).
    const double pushed = -control_.area * stress.sigma_zz - control_.normal_force;
    control_.height_speed +=
        dt * pushed / (control_.mass + dt * control_.area * stress.lid_resistance);
    box.dilation_rate = control_.height_speed / box.length[2];
    return;
  }
  if (control_.rate_controlled) {
    box.shear_velocity = control_.rate * box.length[2];
    return;
  }
  // M dV/dt = A (tau - sigma_zx), forward Euler over the step just taken
  // (image_drive.hpp): the force tau A drives the boundary, the flow's
  // stress across its plane, sigma_zx A, holds it back.
  box.shear_velocity +=
      dt * (control_.drive_force - control_.area * stress.sigma_zx) / control_.mass;
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
// the spec's if it names one. Lz must match: z is periodic (under pressure
// control the height is the state's, whatever it is; its speed W is kept when
// the state was pressure-controlled too).
bool ImageDrive::adopt(const DriveSpec& spec, World& world) {
  if (spec.kind != DriveKind::Images) return false;
  if (!spec.pressure_controlled && world.box.length[2] != spec.size[2]) return false;
  const double w = control_.pressure_controlled ? control_.height_speed : 0.0;
  control_ = control_for(spec, spec.mass > 0.0 ? spec.mass : control_.mass);
  control_.height_speed = spec.pressure_controlled ? w : 0.0;
  world.box.dilation_rate = control_.height_speed / world.box.length[2];
  if (control_.rate_controlled) world.box.shear_velocity = control_.rate * world.box.length[2];
  return true;
}

DriveRecord ImageDrive::record(const World&) const {
  return {.owners = {}, .wall = {}, .images = control_};
}

}  // namespace dilatant
