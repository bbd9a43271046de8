#pragma once
// The shear cell's two rough walls (docs/model.md "Shear cell"): monolayers of
// glued spheres at z = 0 and z = Lz. The bottom wall is fixed (its spheres have
// infinite mass). The top wall is one rigid body that moves along x only (its z
// is fixed: the cell keeps its volume), driven by a constant force F = tau Lx Ly:
//
//     M dV/dt = F + sum_c (force of contact c on a top-wall sphere)_x .
//
// Its spheres have infinite mass in the contact problems; V is solved as its
// own block of the Gauss–Seidel iteration (boundary.hpp) and copied to them.
// The walls' spheres are driven bodies, owned by kBottomWall or kTopWall
// (wall_owner.hpp).
#include <cstdint>
#include <utility>
#include <vector>

#include "boundary/boundary.hpp"
#include "boundary/wall_owner.hpp"

namespace dilatant {

// The top wall's rigid-body state (what a checkpoint keeps).
struct SlidingWall {
  std::vector<std::int32_t> spheres;  // indices into Bodies
  double mass = 0.0;
  double drive_force = 0.0;  // along +x
  double velocity = 0.0;     // along x
};

class RoughWalls final : public Boundary {
 public:
  RoughWalls() = default;
  RoughWalls(SlidingWall top, FrictionLaw law) : top_(std::move(top)), law_(std::move(law)) {}

  const FrictionLaw& contact_law() const override { return law_; }
  void set_contact_law(FrictionLaw law) { law_ = std::move(law); }

  void predict(Bodies& bodies, double dt) override;
  void begin_solve(const std::vector<Contact>& contacts, const Bodies& bodies) override;
  void solve_block(const std::vector<Contact>& contacts, Bodies& bodies) override;
  // The wall's speed is its only state a step changes (predict() recomputes
  // the drive's work and V_free from it).
  // V inside the pass (boundary.hpp): solve_block() sets it exactly after
  // each pass, and the pass's contacts move it in between.
  WallBlock* coupled_block() override { return &block_; }
  void save_state() override { saved_velocity_ = top_.velocity; }
  void restore_state() override { top_.velocity = saved_velocity_; }

  const SlidingWall& top() const { return top_; }
  SlidingWall& top() { return top_; }
  // Kinetic energy of the top wall as a rigid body, M V^2 / 2 (its spheres have
  // infinite mass in Bodies and count nothing there).
  double kinetic_energy() const { return 0.5 * top_.mass * top_.velocity * top_.velocity; }
  // Work of the drive force on the top wall over the last step, F dt (V + V_free)/2
  // (predict()): all it feeds in, the contacts' work on the wall being theirs.
  double drive_work() const { return drive_work_; }

 private:
  SlidingWall top_;
  FrictionLaw law_ = CoulombLaw{};
  // Of the current step: V + dt F / M, the drive's work, and the contacts on the top wall with the
  // sign of their impulse on it (+1 if the wall sphere is body i, -1 if it is the partner).
  double free_velocity_ = 0.0;
  double drive_work_ = 0.0;
  double saved_velocity_ = 0.0;
  WallBlock block_;
  std::vector<std::pair<std::int32_t, double>> top_contacts_;
};

}  // namespace dilatant
