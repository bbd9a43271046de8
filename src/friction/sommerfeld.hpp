#pragma once
// The local Sommerfeld number of a lubricated contact (Fernandez et al. 2013,
// p. 2; docs/model.md "Sommerfeld number"):
//
//     s = eta_f * |v_t| * R_p / N
//
// v_t is the sliding speed at the contact point, N the normal force and R_p the
// reduced radius (geometry/reduced_radius.hpp). Contact Dynamics works with
// impulses over a step, N = p_n / dt, so
//
//     s = k * v_s,    k = eta_f * R_p * dt / p_n,
//
// and k, the Sommerfeld number per unit sliding speed, is what a friction law
// needs: the Stribeck law solves for v_s on the curve mu(k v_s).
namespace dilatant {

// k of a contact that carries the normal impulse p_n > 0 over dt. A contact
// without load (p_n = 0) carries no friction; callers must not ask for its s.
inline double sommerfeld_per_speed(double eta_f, double reduced_radius, double dt,
                                   double normal_impulse) {
  return eta_f * reduced_radius * dt / normal_impulse;
}

// s of a contact sliding at v_s, given its k (sommerfeld_per_speed).
inline double sommerfeld_number(double per_speed, double sliding_speed) {
  return per_speed * sliding_speed;
}

}  // namespace dilatant
