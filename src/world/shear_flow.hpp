#pragma once
// A simple shear flow along x with its gradient along z,
//
//     u_x(z) = shear_rate (z - z0),
//
// the mean flow of a sheared cell: what the drive imposes (boundary/drive.hpp),
// what the fluid's drag is taken relative to (fluid/stokes_drag.hpp) and what
// the particle stress's kinetic part subtracts (measure/particle_stress.hpp).
// shear_rate = 0 is a fluid at rest.

namespace dilatant {

struct ShearFlow {
  double shear_rate = 0.0;  // gamma_dot
  double z0 = 0.0;          // height where the flow is at rest
};

}  // namespace dilatant
