#pragma once
// Stokes drag of the fluid on each sphere, relative to an imposed flow:
//
//     F_i = -6 pi eta_f r_i (v_i - U(x_i)),    T_i = -8 pi eta_f r_i^3 (w_i - Omega)
//
// (Stokes 1851; Kim & Karrila 1991, Sec. 2.3 for the torque). The ambient flow
// is simple shear along x with gradient along z,
//
//     U(x) = (gamma_dot (z - z0), 0, 0),    Omega = (0, gamma_dot / 2, 0),
//
// Omega being half the vorticity curl U = (0, gamma_dot, 0): a sphere that
// follows the flow feels no drag and no torque. gamma_dot = 0 is a fluid at
// rest (a scene). In the shear cell gamma_dot and z0 follow the walls (the
// linear profile between them at the current wall speed: drivers/shear_cell.cpp),
// the mean-field picture of Trulsson, Andreotti & Claudin (2012, PRL 109, 118305).
// Taken implicitly through the body's effective mass (fluid/fluid_forces.hpp).
#include "fluid/fluid_forces.hpp"
#include "world/shear_flow.hpp"

namespace dilatant {

struct StokesDrag {
  double eta_f = 0.0;

  // Fills `drag` for every body of `world` (fixed bodies get coefficients too;
  // the implicit update leaves them alone).
  void assign(const World& world, const ShearFlow& flow, BodyDrag& drag) const;
};

}  // namespace dilatant
