#pragma once
// Squeeze-film lubrication between two close surfaces (normal part only).
//
// Two spheres of radii r_i, r_j whose surfaces are a gap h apart and approach
// (or separate) at the normal speed u_n resist with the Reynolds force
//
//     F = -6 pi eta_f a*^2 u_n / h,      a* = r_i r_j / (r_i + r_j)
//
// (Kim & Karrila 1991, Microhydrodynamics, Sec. 9.3; a* = r against a plane,
// where it is Brenner's 1961 limit h << r). It diverges at contact, where hard
// spheres touch; as in LF-DEM (Mari, Seto, Morris & Denn 2014, J. Rheol. 58,
// 1693, Eq. 4) it is regularised by delta, h -> h + delta, and cut off beyond a
// largest gap h_c, where the far-field (drag, fluid/stokes_drag.hpp) takes over:
//
//     F = -c u_n,    c = 6 pi eta_f a*^2 / (max(h, 0) + delta)   for h < h_c.
//
// Lengths delta and h_c are in units of the pair's mean radius (r_i + r_j)/2
// (r_i against a plane). LF-DEM's choice is delta = 1e-3, h_c = 0.5.
//
// Implicit in time: h is the gap at the start of the step, u_n the normal
// relative velocity at its end, so the film's impulse over the step is
//
//     p_lub = -k u_n+,   k = c dt,
//
// linear in the unknown velocities. It joins the contact's own local problem in
// the Gauss–Seidel sweep (solver/local_problem.hpp, solve_normal_with_film): a
// stiff film (k w_n >> 1, the viscous time m/c far below dt) stays stable and
// reaches the closed-form approach of two spheres for any dt.
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

struct SqueezeFilm {
  double eta_f = 0.0;            // fluid viscosity
  double cutoff = 0.5;           // largest gap h_c, in mean radii
  double regularization = 1e-3;  // delta, in mean radii

  // c(h) of one pair (radii r_i, r_j; r_j = 0 for a plane); 0 beyond the cut-off.
  double resistance(double gap, double r_i, double r_j) const;
  // The largest surface gap a film can act across, for radii up to r_max.
  double range(double r_max) const { return cutoff * r_max; }
  // Sets every contact's `lubrication` = c dt (0 beyond the cut-off).
  void assign(std::vector<Contact>& contacts, double dt) const;
};

}  // namespace dilatant
