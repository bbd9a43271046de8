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

  // Whether predict() ran in this step (until restore_masses()).
  bool active() const { return active_; }
  // Swaps the velocities predict() found, before the drag acted, with those in
  // `bodies` (call twice to undo): a look at them without copying the bodies.
  void swap_predicted_velocities(Bodies& bodies) {
    bodies.velocity.swap(velocity_);
    bodies.angular_velocity.swap(angular_velocity_);
  }
  // The drag's work over the step, given the end-of-step velocities in `bodies`:
  //     sum_i J_i . (v_i,pred + v_i,end) / 2,   J_i = -dt zeta_i (v_i,end - U_i)
  // (and alike for rotation). Since m (v_end - v_pred) = J_drag + J_contacts
  // exactly, this and the contacts' work taken from the predicted velocities
  // (solver/contact_work.hpp) add up to KE(end) - KE(pred) to round-off.
  double work(const BodyDrag& drag, double dt, const Bodies& bodies) const;

 private:
  bool active_ = false;
  bool swapped_ = false;
  std::vector<double> inv_mass_, inv_inertia_;     // the other set of the two
  std::vector<Vec3> velocity_, angular_velocity_;  // predicted, before the drag
};

}  // namespace dilatant
