#pragma once
// The simulation box: lengths and which axes wrap around.
// Non-periodic axes are unbounded (walls and planes confine the particles there).
//
// Lees–Edwards images (Lees & Edwards, J. Phys. C 5, 1921 (1972); Allen &
// Tildesley, "Computer Simulation of Liquids", 2nd ed., section 2.5.2): with
// z periodic and `lees_edwards` set, the copy of the box above (z + Lz) is
// displaced by `shear_offset` along x and moves at `shear_velocity` along x;
// the copy below by minus both. A homogeneous shear u_x = gamma_dot z then
// looks the same from every copy: offset = gamma_dot Lz t (mod Lx), velocity
// = gamma_dot Lz. A body leaving through the top re-enters at the bottom
// shifted by -offset in x, its velocity by -velocity; a pair seen across z
// meets the partner's image, whose x velocity differs by +-velocity.
#include <array>
#include <cmath>

#include "geometry/vec3.hpp"

namespace dilatant {

struct PeriodicBox {
  Vec3 length = Vec3::Zero();
  std::array<bool, 3> periodic = {false, false, false};
  bool lees_edwards = false;    // needs periodic[0] and periodic[2]
  double shear_offset = 0.0;    // x displacement of the copy above, in [0, Lx)
  double shear_velocity = 0.0;  // x velocity of the copy above
  // The box's affine dilation rate along z, eps_dot = W / Lz, under the
  // Lees–Edwards pressure control (boundary/image_drive.hpp): the height grows
  // at W and every body is carried with it, z -> (1 + eps_dot dt) z, besides
  // its own velocity. Two bodies d apart (d from the partner to the body) then
  // separate at eps_dot d_z along z beyond their velocities' difference
  // (Contact::dilation_drift); 0 under every other drive.
  double dilation_rate = 0.0;

  // The nearest image of b seen from a: d = a - b', and which copy along z
  // b' lies in (b' = b + image (offset, 0, Lz) before the x and y wraps), so
  // that b' moves at v_b + image * shear_velocity along x.
  struct Image {
    Vec3 d;
    int image = 0;
  };
  Image nearest_image(const Vec3& a, const Vec3& b) const {
    Image out{a - b, 0};
    if (periodic[2]) {
      out.image = static_cast<int>(std::round(out.d[2] / length[2]));
      out.d[2] -= out.image * length[2];
      if (lees_edwards) out.d[0] -= out.image * shear_offset;
    }
    for (int k = 0; k < 2; ++k) {
      if (periodic[k]) out.d[k] -= length[k] * std::round(out.d[k] / length[k]);
    }
    return out;
  }

  // Shortest vector from b to a, taking the nearest periodic image of b.
  Vec3 minimum_image(const Vec3& a, const Vec3& b) const { return nearest_image(a, b).d; }

  // Maps a position back into [0, L) along every periodic axis (a body
  // crossing z under Lees–Edwards is shifted in x too: wrap_body()).
  Vec3 wrap(Vec3 x) const {
    Vec3 v = Vec3::Zero();
    wrap_body(x, v);
    return x;
  }

  // Maps a body back into the box, with the velocity it has there: across z
  // under Lees–Edwards, x - k offset and v_x - k velocity for k copies up.
  void wrap_body(Vec3& x, Vec3& v) const {
    if (periodic[2]) {
      const double k = std::floor(x[2] / length[2]);
      x[2] -= k * length[2];
      if (lees_edwards) {
        x[0] -= k * shear_offset;
        v[0] -= k * shear_velocity;
      }
    }
    for (int k = 0; k < 2; ++k) {
      if (periodic[k]) x[k] -= length[k] * std::floor(x[k] / length[k]);
    }
  }

  // Moves the copies on by one step of the shear (the offset kept in [0, Lx)).
  void advance_shear(double dt) {
    if (!lees_edwards) return;
    shear_offset += shear_velocity * dt;
    shear_offset -= length[0] * std::floor(shear_offset / length[0]);
  }
};

}  // namespace dilatant
