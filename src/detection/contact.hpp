#pragma once
// One potential contact between a sphere i and either another sphere j or a
// fixed plane k (stored as other = -(k+1)). Everything the solver needs for the
// contact is computed once per step by the detector and kept in this record.
#include <cstdint>

#include "friction/tangential_problem.hpp"
#include "geometry/vec3.hpp"

namespace dilatant {

struct Contact {
  std::int32_t i = 0;           // sphere index
  std::int32_t other = 0;       // sphere index j >= 0, or -(k+1) for plane k
  Vec3 normal = Vec3::UnitZ();  // unit normal from the partner towards i
  double gap = 0.0;             // surface separation at the start of the step (< 0: overlap)
  double arm_i = 0.0;           // r_i: contact point is x_i - r_i n
  double arm_j = 0.0;           // r_j: contact point is x_j + r_j n (0 for a plane)
  double reduced_radius = 0.0;  // R_p of the Sommerfeld number
  double w_n = 0.0;             // normal Delassus coefficient 1/m_i + 1/m_j
  double w_t = 0.0;             // tangential one, adds r^2/I for each sphere
  // x velocity of the partner's image relative to the partner: k V for an
  // image k copies up across a Lees–Edwards boundary (geometry/periodic_box.hpp).
  double image_drift = 0.0;
  // z velocity of i relative to the partner from the box's affine dilation,
  // eps_dot d_z with d = x_i - x_partner (PeriodicBox::dilation_rate): the
  // part of the pair's approach the lid's motion makes (pressure control).
  double dilation_drift = 0.0;

  // Squeeze-film resistance of the pair over the step (fluid/squeeze_film.hpp):
  // its impulse is -lubrication * u_n at the end of the step (0: none).
  double lubrication = 0.0;

  // Unknowns: impulses over the step, applied to i (and minus to j).
  double p_n = 0.0;         // contact (Signorini), >= 0
  Vec3 p_t = Vec3::Zero();  // friction, perpendicular to normal
  double p_lub = 0.0;       // squeeze film along the normal, either sign

  // Outcome of the last local solve (for measurements and output).
  double sliding_speed = 0.0;
  double sommerfeld = 0.0;
  Regime regime = Regime::Open;
  // Regime at the end of the previous step (Open for a new contact): the HD
  // branch is kept from step to step while it exists (friction/stribeck_law.hpp).
  Regime previous_regime = Regime::Open;

  bool with_plane() const { return other < 0; }
  int plane_index() const { return -other - 1; }
};

// What a contact carries to the next step: its world-frame impulse (warm start)
// and its friction regime.
struct ContactMemory {
  Vec3 impulse = Vec3::Zero();
  Regime regime = Regime::Open;
};

// Identity of a contact across steps, for warm starting.
inline std::uint64_t contact_key(const Contact& c) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.i)) << 32) |
         static_cast<std::uint32_t>(c.other);
}

}  // namespace dilatant
