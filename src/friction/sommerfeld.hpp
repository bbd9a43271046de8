#pragma once
// The local Sommerfeld number of a lubricated contact (SPEC §1; paper p.2):
//
//     s = eta_f * |v_t| * R_p / N
//
// v_t is the sliding speed at the contact point, N the normal force, and R_p the
// reduced radius 2 r_i r_j / (r_i + r_j): r for two equal spheres, 2r for a sphere
// on a flat plane (r_j -> infinity).
namespace dilatant {

inline double reduced_radius(double r_i, double r_j) { return 2.0 * r_i * r_j / (r_i + r_j); }
inline double reduced_radius_on_plane(double r) { return 2.0 * r; }

// A contact without load (N = 0) carries no friction; callers must not ask for its s.
inline double sommerfeld_number(double eta_f, double sliding_speed, double r_p,
                                double normal_force) {
  return eta_f * sliding_speed * r_p / normal_force;
}

}  // namespace dilatant
