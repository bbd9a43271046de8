#pragma once
// Applies a BodyDrag implicitly to one step (fluid/fluid_forces.hpp): each
// dragged body gets its free velocity
//     v_free = (m v_pred + dt zeta U) / (m + dt zeta)
// and, for the contact detection and solve only, the effective inverse mass
// 1 / (m + dt zeta) (rotation alike), so that the contact impulses act on the
// body as the implicit drag makes it respond. Everything else (kinetic energy,
// output) sees the true masses.
#include <vector>

#include "fluid/fluid_forces.hpp"
#include "world/bodies.hpp"

namespace dilatant {

class ImplicitDrag {
 public:
  // Turns the predicted velocities into the free velocities of this step and
  // prepares the effective masses. Fixed bodies (inverse mass 0) are left
  // alone. Throws std::invalid_argument if a non-empty vector of `drag` does
  // not have one entry per body.
  void predict(const BodyDrag& drag, double dt, Bodies& bodies);
  // Puts the effective inverse masses into `bodies` / the true ones back. Both
  // do nothing unless predict() ran in this step.
  void use_effective_masses(Bodies& bodies);
  void restore_masses(Bodies& bodies);

 private:
  bool active_ = false;
  bool swapped_ = false;
  std::vector<double> inv_mass_, inv_inertia_;  // the other set of the two
};

}  // namespace dilatant
