#pragma once
// The Lees–Edwards boundary of the wall-free shear cell (docs/shear-cell.md
// "The Lees–Edwards cell"): the box is periodic in x, y and z, and the copy of
// the box above (z + Lz) slides along x at the boundary speed V (Lees &
// Edwards, J. Phys. C 5, 1921 (1972); Allen & Tildesley, "Computer Simulation
// of Liquids", 2nd ed. (2017), section 2.5.2). A homogeneous shear
// u_x = gamma_dot (z - Lz/2) looks the same from every copy when
// V = gamma_dot Lz, so V is the boundary's one degree of freedom. The images'
// offset and speed live in the box (geometry/periodic_box.hpp), which contact
// detection and the contacts' relative velocity (Contact::image_drift) read.
//
// Control:
//   rate    V = gamma_dot Lz, fixed.
//   stress  V follows the stress the flow transmits, with a fictitious inertia
//           M: the form of Parrinello & Rahman's coupling of a box degree of
//           freedom to the stress (J. Appl. Phys. 52, 7182 (1981): a
//           fictitious mass driven by the imposed minus the measured stress),
//           as used for the pressure under Lees–Edwards shear by Chialvo, Sun
//           & Sundaresan, Phys. Rev. E 85, 021305 (2012); here it acts on the
//           shear stress and V, written as the equation of motion of the wall
//           it replaces, so that M has the wall's meaning:
//
//               M dV/dt = A (tau - sigma_zx),     A = Lx Ly,
//
//           sigma_zx the particle stress of the step (measure/particle_stress.hpp).
//           This is exactly the wall cell's top wall (boundary/rough_walls.hpp),
//           M dV/dt = F + (contact force on it), with the contacts' force per
//           area on a wall replaced by the bulk stress, which a homogeneous flow
//           transmits across every plane z = const alike.
//
// V is constant within a step: the contact problem sees images moving at V,
// as detection and the relative velocity already do, and the boundary has no
// bodies and no block of its own in the Gauss–Seidel iteration (its Boundary
// hooks do nothing). Between steps, respond() advances V explicitly from the
// step's measured stress (forward Euler): V_{n+1} = V_n + dt A (tau - sigma_n) / M.
// An explicit update is stable while dt A d(sigma)/dV / M < 2, with
// d(sigma)/dV = eta / Lz; the automatic step keeps dt far below that (it bounds
// the drive's displacement per step: drive_acceleration()).
#include "boundary/boundary.hpp"
#include "geometry/periodic_box.hpp"

namespace dilatant {

// What a checkpoint keeps besides the box's offset and speed (V itself lives in
// PeriodicBox::shear_velocity, the one place everything reads it from).
struct LeesEdwardsDrive {
  double mass = 0.0;         // M, fictitious (stress control)
  double drive_force = 0.0;  // tau A, along +x (stress control)
  double area = 0.0;         // A = Lx Ly
  double rate = 0.0;         // gamma_dot imposed (rate control), else 0
  bool rate_controlled = false;
};

class LeesEdwards final : public Boundary {
 public:
  LeesEdwards() = default;
  explicit LeesEdwards(LeesEdwardsDrive drive) : drive_(drive) {}

  // No bodies of its own: contacts are all particle-particle (their law).
  std::span<const BodyGroup> body_groups() const override { return {}; }
  const FrictionLaw& contact_law() const override { return unused_law_; }
  // V is constant within a step (above): nothing to solve in the contact problem.
  void predict(Bodies&, double) override {}
  void begin_solve(const std::vector<Contact>&) override {}
  void solve_block(const std::vector<Contact>&, Bodies&) override {}

  // After a step of length dt whose measured shear stress was sigma_zx: the
  // boundary speed of the next step (stress control; rate control keeps V).
  void respond(PeriodicBox& box, double sigma_zx, double dt) const;

  // The acceleration the drive alone gives the boundary, tau A / M (0 under
  // rate control): the automatic step bounds the displacement it causes, as
  // it does the wall's (drivers/shear_cell.cpp, choose_dt()).
  double drive_acceleration() const {
    return drive_.rate_controlled ? 0.0 : drive_.drive_force / drive_.mass;
  }
  // Power the boundary feeds into the flow, A V sigma_zx (the work of the
  // images on the box; Evans & Morriss, "Statistical Mechanics of
  // Nonequilibrium Liquids", 2nd ed. (2008), section 6.3: the dissipation
  // of homogeneous shear is -sigma_zx gamma_dot times the volume).
  double power(const PeriodicBox& box, double sigma_zx) const {
    return drive_.area * box.shear_velocity * sigma_zx;
  }

  const LeesEdwardsDrive& drive() const { return drive_; }
  LeesEdwardsDrive& drive() { return drive_; }

 private:
  LeesEdwardsDrive drive_;
  FrictionLaw unused_law_ = CoulombLaw{};
};

}  // namespace dilatant
