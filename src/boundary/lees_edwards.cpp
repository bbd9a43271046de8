#include "boundary/lees_edwards.hpp"

namespace dilatant {

void LeesEdwards::respond(PeriodicBox& box, double sigma_zx, double dt) const {
  if (drive_.rate_controlled) {
    box.shear_velocity = drive_.rate * box.length[2];
    return;
  }
  // M dV/dt = A (tau - sigma_zx), forward Euler over the step just taken
  // (lees_edwards.hpp): the force tau A drives the boundary, the flow's
  // stress across its plane, sigma_zx A, holds it back.
  box.shear_velocity += dt * (drive_.drive_force - drive_.area * sigma_zx) / drive_.mass;
}

}  // namespace dilatant
