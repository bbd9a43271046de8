#pragma once
// Forces of the fluid that depend on the bodies' velocities (Stokes drag and
// squeeze-film lubrication), and where they enter the time step.
//
// Such forces are stiff: a drag time m/zeta far below dt would make an explicit
// update blow up. They are therefore taken implicitly, linear in the
// end-of-step velocities v+ and w+ (Moreau–Jean, theta = 1):
//
//     F_i = -zeta_i (v_i+ - U_i),     T_i = -xi_i (w_i+ - Omega_i),
//
// with U_i and Omega_i the fluid's velocity and spin at body i. Then
//
//     m (v+ - v) = dt (m g + F_ext) - dt zeta (v+ - U) + P_contacts
//  => (m + dt zeta) v+ = m v_pred + dt zeta U + P_contacts,
//
// v_pred = v + dt (g + F_ext/m) the prediction without fluid. So the contact
// problem sees body i with the effective mass m + dt zeta (and moment of
// inertia I + dt xi) and the free velocity
//
//     v_free = (m v_pred + dt zeta U) / (m + dt zeta),
//
// which is unconditionally stable and reaches the exact steady states (a
// sphere sedimenting under gravity ends at U + m g / zeta for any dt);
// fluid/implicit_drag.hpp applies it. Pair forces (the squeeze film between two
// close surfaces, linear in their relative normal velocity) enter the same
// implicit step as part of each pair's local problem in the Gauss–Seidel sweep
// (fluid/squeeze_film.hpp, solver/local_problem.hpp).
#include <vector>

#include "detection/contact.hpp"
#include "geometry/vec3.hpp"
#include "world/world.hpp"

namespace dilatant {

// Per-body coefficients of the implicit drag for one step. An empty vector
// means none of that kind (no translational drag, fluid at rest, ...).
struct BodyDrag {
  std::vector<double> translational;  // zeta_i, force per velocity
  std::vector<Vec3> fluid_velocity;   // U_i
  std::vector<double> rotational;     // xi_i, torque per angular velocity
  std::vector<Vec3> fluid_spin;       // Omega_i

  bool empty() const { return translational.empty() && rotational.empty(); }
  void clear() {
    translational.clear();
    fluid_velocity.clear();
    rotational.clear();
    fluid_spin.clear();
  }
};

class FluidForces {
 public:
  virtual ~FluidForces() = default;
  // The drag on each body for the step about to be taken (world as predicted:
  // positions and velocities at the start of the step). Leave `drag` empty for none.
  virtual void body_drag(const World& world, BodyDrag& drag) const = 0;
  // Pair forces: the largest surface gap they act across (the contact detector
  // looks at least that far), and each found pair's coefficient for the step
  // (Contact::lubrication). None by default.
  virtual double pair_range(const World& /*world*/) const { return 0.0; }
  virtual void pair_resistance(std::vector<Contact>& /*contacts*/, double /*dt*/) const {}
};

}  // namespace dilatant
