#pragma once
// The drive of the wall-free shear cell (docs/shear-cell.md "The Lees–Edwards
// cell"): the box is periodic in x, y and z, and the copy of the box above
// (z + Lz) slides along x at the boundary speed V (Lees & Edwards, J. Phys. C
// 5, 1921 (1972); Allen & Tildesley, "Computer Simulation of Liquids", 2nd ed.
// (2017), section 2.5.2). A homogeneous shear u_x = gamma_dot (z - Lz/2) looks
// the same from every copy when V = gamma_dot Lz, so V is the drive's one
// degree of freedom. The images' offset and speed live in the box
// (geometry/periodic_box.hpp), which contact detection and the contacts'
// relative velocity (Contact::image_drift) read.
//
// Control:
//   rate    V = gamma_dot Lz, fixed.
//   pressure  V = gamma_dot Lz as under rate control, and the box height
//           H = Lz follows the normal stress P = -sigma_zz imposed (the set-up
//           of Boyer, Guazzelli & Pouliquen, PRL 107, 188301 (2011): rate and
//           pressure imposed, phi and tau measured). H is a degree of freedom
//           of fictitious mass M and speed W, Parrinello & Rahman's barostat
//           (J. Appl. Phys. 52, 7182 (1981)) restricted to the one length Lz,
//           as in the pressure-controlled Lees–Edwards shear of da Cruz et al.,
//           Phys. Rev. E 72, 021309 (2005) and Chialvo, Sun & Sundaresan, PRE
//           85, 021305 (2012):
//
//               M dW/dt = A (p - P),   dH/dt = W,   p = -sigma_zz,
//
//           the box a lid of mass M pressed down by P A and pushed up by the
//           normal stress the flow transmits. The lid is in the contacts: the
//           box dilates affinely at eps_dot = W / H (PeriodicBox::
//           dilation_rate), every body carried along z at eps_dot z besides
//           its own (peculiar) velocity, so a pair d apart separates at
//           eps_dot d_z besides (Contact::dilation_drift): the inelastic
//           contacts and the squeeze films resist the approach a compressing
//           lid makes, and the gaps the solve predicts are those the bodies
//           end with. Between steps (respond), with p measured over the step
//           just taken: first the dilation the step saw, s = (H + W dt) / H,
//           every z -> s z (positions stay inside [0, sH), images stay
//           images), H -> s H; then the lid's speed, linearly implicit in the
//           films' response c = -dp/dW (boundary/lid_resistance.hpp):
//
//               W += dt A (p - P) / (M + dt A c),
//
//           the implicit Euler step of M dW/dt = A (p(W) - P) with
//           p(W) = p_n - c (W - W_n). The flow answers the lid with a
//           damping; an explicit step multiplies the lid's departure from its
//           terminal speed by 1 - dt A c / M, far below -1 for stiff films
//           and a light lid (it bounced: docs/shear-cell.md), the implicit one
//           by 1 - dt A c_true / (M + dt A c), in [0, 1) since the bodies
//           held fixed make c >= c_true. Then V = gamma_dot H and eps_dot =
//           W / H. Velocities are not rescaled (Parrinello & Rahman's
//           peculiar velocities obey a term -2 eps_dot v, of order W dt / H a
//           step). time_step_bound() keeps the lid's displacement per step
//           below the reach, as for the boundary under stress control.
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
//           This is exactly the wall cell's top wall (wall_drive.hpp),
//           M dV/dt = F + (contact force on it), with the contacts' force per
//           area on a wall replaced by the bulk stress, which a homogeneous flow
//           transmits across every plane z = const alike.
//
// V is constant within a step: the contact problem sees images moving at V,
// as detection and the relative velocity already do, and the drive has no
// bodies and no block of its own in the Gauss–Seidel iteration
// (contact_block() is null). Between steps, respond() advances V explicitly
// from the step's measured stress (forward Euler):
// V_{n+1} = V_n + dt A (tau - sigma_n) / M. An explicit update is stable while
// dt A d(sigma)/dV / M < 2, with d(sigma)/dV = eta / Lz; the automatic step
// keeps dt far below that (it bounds the drive's displacement per step:
// time_step_bound()).
#include "boundary/drive.hpp"

namespace dilatant {

// What a checkpoint keeps besides the box's offset and speed (V itself lives in
// PeriodicBox::shear_velocity, the one place everything reads it from).
struct ImageControl {
  double mass = 0.0;         // M, fictitious (stress control)
  double drive_force = 0.0;  // tau A, along +x (stress control)
  double area = 0.0;         // A = Lx Ly
  double rate = 0.0;         // gamma_dot imposed (rate control), else 0
  bool rate_controlled = false;
  // Pressure control (rate_controlled too; `mass` is then the height's M).
  bool pressure_controlled = false;
  double normal_force = 0.0;  // P A, pushing the box's height down
  double height_speed = 0.0;  // W = dH/dt
};

class ImageDrive final : public Drive {
 public:
  explicit ImageDrive(ImageControl control) : control_(control) {}

  // The control `spec` asks for, with this fictitious mass M.
  static ImageControl control_for(const DriveSpec& spec, double mass);

  std::string_view name() const override { return "lees-edwards"; }
  std::string_view mover() const override { return "boundary"; }

  // No bodies, no block: every contact is between particles, under their law.
  Boundary* contact_block() override { return nullptr; }
  void set_contact_law(FrictionLaw) override {}
  double time_step_bound(const World& world, double reach, double span) const override;
  double fed_work(const World& world, double sigma_zx, double dt) const override {
    return fed_power(world, sigma_zx) * dt;
  }
  void respond(World& world, const StepStress& stress, double dt) override;

  double speed(const World& world) const override { return world.box.shear_velocity; }
  ShearFlow mean_flow(const World& world) const override;
  // V is not a body's: the images' fictitious inertia holds no energy of the flow.
  double kinetic_energy() const override { return 0.0; }

  bool bounded_by_walls() const override { return false; }
  WallForces wall_forces(const World&, const std::vector<Contact>&, double) const override {
    return {};
  }
  double normal_stress(const World&, const WallForces&, double sigma_zz) const override {
    return -sigma_zz;
  }
  BulkRegion bulk_region(const World& world) const override;

  bool adopt(const DriveSpec& spec, World& world) override;
  DriveRecord record(const World& world) const override;

  // Power the images feed into the flow, A V sigma_zx (the work of the images
  // on the box; Evans & Morriss, "Statistical Mechanics of Nonequilibrium
  // Liquids", 2nd ed. (2008), section 6.3: the dissipation of homogeneous
  // shear is -sigma_zx gamma_dot times the volume).
  double fed_power(const World& world, double sigma_zx) const {
    return control_.area * world.box.shear_velocity * sigma_zx;
  }
  const ImageControl& control() const { return control_; }

  // The affine dilation of the box in z by s > 0 (pressure control): every
  // body's z -> s z, Lz -> s Lz, and under rate control V = gamma_dot Lz.
  void dilate(World& world, double s) const;

 private:
  ImageControl control_;
};

}  // namespace dilatant
