#pragma once
// The reduced (effective) radius of two touching spheres,
//
//     R_p = 2 r_i r_j / (r_i + r_j),
//
// r for two equal spheres and 2r for a sphere on a flat plane (r_j -> infinity).
// It is the length of the paper's Sommerfeld number (Fernandez et al. 2013, p. 2;
// docs/model.md "Sommerfeld number"): twice the harmonic mean is the radius of
// the sphere that, against a plane, has the same gap profile h(x) near the contact.
namespace dilatant {

inline double reduced_radius(double r_i, double r_j) { return 2.0 * r_i * r_j / (r_i + r_j); }
inline double reduced_radius_on_plane(double r) { return 2.0 * r; }

}  // namespace dilatant
