#pragma once
// What drives a flow from its edges: the seam between the generic Contact
// Dynamics step (solver/time_stepper.hpp) and a particular cell.
//
// A boundary owns degrees of freedom of its own (the shear cell's top wall: its
// velocity V along x) and the driven bodies whose motion those degrees of
// freedom set (world/bodies.hpp: the wall's glued spheres, of infinite mass in
// every contact problem; the boundary numbers its parts by their owner id).
// The step calls it at three fixed points:
//
//   predict      stage 1, no contacts: advance the own degrees of freedom under
//                their drive, V_free = V + dt F / M, and give the boundary's
//                bodies their free velocities;
//   begin_solve  after detection and warm start: note which contacts act on it;
//   solve_block  once before the first Gauss–Seidel sweep and after every sweep:
//                solve the own degrees of freedom exactly given the contacts'
//                current impulses (one more block of the nonlinear Gauss–Seidel,
//                Jean 1999), V = V_free + (1/M) sum_c P_c,x, and copy it to its
//                bodies. It runs on one thread while others already sweep the
//                next even slabs (solver/slab_partition.hpp): it may write only
//                bodies that contacts of even slabs do not touch.
//
// A step whose solve does not converge is undone and redone at half its
// length (solver/time_stepper.hpp): save_state() before stage 1 keeps the own
// degrees of freedom, restore_state() puts them back.
//
// Contacts touching a driven body obey the boundary's own contact law
// (contact_law()), e.g. the walls' rough-grain Coulomb friction. Which bodies
// are driven is written on the bodies themselves (Bodies::motion), so the
// solver asks a body what it does, never the boundary whose it is.
//
// A cell's drive (drive.hpp) hands the stepper its block through this seam,
// or none: the Lees–Edwards images (image_drive.hpp) keep their speed
// constant within a step and have no bodies, so they take no part in the
// contact problem; their offset and speed live in the PeriodicBox, which
// detection and the contacts' relative velocity read.
#include <vector>

#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "world/bodies.hpp"

namespace dilatant {

// A degree of freedom of a boundary that moves its bodies rigidly along x
// (the shear cell's top wall), solved inside the Gauss–Seidel pass as one
// more body: each contact on one of its bodies sees the wall's compliance
// 1/M in its local problem, and moves V by its impulse change at once,
// V += sign dP_x / M (solver/contact_solver.cpp). Without it the wall's few
// hundred contacts push together as if it were fixed and V jumps by their sum
// once per pass: a Jacobi block, which oscillates when the wall is light
// against stiff contacts (docs/shear-cell.md "Dynamics").
struct WallBlock {
  double velocity = 0.0;     // V, current within the pass
  double inv_mass = 0.0;     // 1/M
  OwnerId owner = kNoOwner;  // the owner id of its bodies
};

class Boundary {
 public:
  virtual ~Boundary() = default;

  // The law of contacts that touch a driven body.
  virtual const FrictionLaw& contact_law() const = 0;

  virtual void predict(Bodies& bodies, double dt) = 0;
  virtual void begin_solve(const std::vector<Contact>& contacts, const Bodies& bodies) = 0;
  virtual void solve_block(const std::vector<Contact>& contacts, Bodies& bodies) = 0;
  // The degree of freedom solved inside the pass, if any (null: none; its
  // bodies are then fixed within the pass, as a fixed wall's).
  virtual WallBlock* coupled_block() = 0;
  virtual void save_state() = 0;
  virtual void restore_state() = 0;
};

}  // namespace dilatant
