#pragma once
// One Contact Dynamics time step (Moreau–Jean, theta = 1), in explicit stages:
//
//   1. predict    v_free = v + dt (g + F_ext/m)          (no contacts);
//                 the boundary's own free motion (boundary/boundary.hpp);
//                 the fluid's implicit drag (fluid/fluid_forces.hpp)
//   2. detect     contacts whose gap may close within the step (cell list),
//                 and pairs within reach of the fluid's squeeze films
//   3. warm start impulses of contacts that existed last step
//   4. solve      nonlinear Gauss–Seidel until the stopping test holds
//                 (solver/contact_solver.hpp), the boundary's block solved
//                 after every pass; the residual of the contact problem
//                 (solver/contact_residual.hpp) is reported
//   5. store      impulses for the next step's warm start
//   6. integrate  x += dt v   with the end-of-step velocities (implicit)
//
// Collisions are perfectly inelastic in the normal direction (zero restitution).
// The stepper knows no particular cell: a boundary and fluid forces are given
// to it (both optional; without them it integrates a plain granular world).
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include "boundary/boundary.hpp"
#include "detection/contact_detector.hpp"
#include "fluid/fluid_forces.hpp"
#include "fluid/implicit_drag.hpp"
#include "friction/friction_law.hpp"
#include "solver/contact_residual.hpp"
#include "solver/contact_solver.hpp"
#include "solver/contact_work.hpp"
#include "world/world.hpp"

namespace dilatant {

struct StepReport {
  SolveReport solve;
  ContactResidual contact_residual;  // of the impulses the solve ended with
  std::size_t contacts_detected = 0;
  std::size_t contacts_closed = 0;        // contacts carrying a normal impulse
  double kinetic_energy_free = 0.0;       // after prediction, before drag and contacts act
  double kinetic_energy = 0.0;            // at the end of the step
  double max_overlap = 0.0;               // largest overlap at the end of the step ...
  std::int32_t max_overlap_contact = -1;  // ... at this index of contacts() (-1: none)
  ContactWork contact_work;               // KE(end) - KE(free) by contact kind ...
  double drag_work = 0.0;                 // ... and the drag's share (fluid/implicit_drag.hpp)
  double detection_seconds = 0.0;         // stages 2-3: detection, slab order, warm start
  double solve_seconds = 0.0;             // stage 4
};

// A state the step cannot continue from (a non-finite body). Drivers add the
// step and strain to the message and stop the run.
class NumericalFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TimeStepper {
 public:
  TimeStepper(FrictionLaw law, SolverSettings settings, double dt)
      : law_(std::move(law)), settings_(settings), dt_(dt) {}

  // Advances `world` by one step; `boundary` (may be null) is advanced with it.
  StepReport step(World& world, Boundary* boundary = nullptr);

  // Velocity-dependent fluid forces, taken implicitly (null: none). Not owned:
  // it must outlive the stepper's use of it.
  void set_fluid_forces(const FluidForces* fluid) { fluid_ = fluid; }
  void set_dt(double dt) { dt_ = dt; }
  // Called after every pass of the solve (solver/contact_problem.hpp); empty: none.
  void set_pass_observer(PassObserver observer) { pass_observer_ = std::move(observer); }
  // The solver's cap on the push-out speed of overlaps (SolverSettings).
  void set_max_push_out(double speed) { settings_.max_push_out = speed; }
  // The residual's unit for the next steps (SolverSettings::reference_impulse):
  // the driver's, from the load it applies and the step it chose.
  void set_reference_impulse(double impulse) { settings_.reference_impulse = impulse; }
  double dt() const { return dt_; }
  const SolverSettings& settings() const { return settings_; }
  const FrictionLaw& law() const { return law_; }
  // Contacts of the last step with their impulses and friction regimes.
  const std::vector<Contact>& contacts() const { return contacts_; }
  // How contacts() is ordered into red-black slabs for the passes.
  const SlabPartition& slabs() const { return slabs_; }

  // What the contacts of the last step pass to the next (by contact key), for
  // checkpoints.
  const std::unordered_map<std::uint64_t, ContactMemory>& contact_memory() const { return memory_; }
  void restore_contact_memory(std::unordered_map<std::uint64_t, ContactMemory> memory) {
    memory_ = std::move(memory);
  }

 private:
  double detection_margin(const World& world) const;
  void warm_start(Bodies& bodies);
  // Relative velocity at every contact of contacts_, for contact_work.
  void relative_velocities(const Bodies& bodies, std::vector<Vec3>& out) const;
  // The largest overlap at the end of the step and its contact (the first of
  // equal ones: the same whatever the threads).
  std::pair<double, std::int32_t> largest_overlap(const World& world) const;

  FrictionLaw law_;
  const FluidForces* fluid_ = nullptr;
  BodyDrag drag_;  // of the current step, reused
  ImplicitDrag implicit_drag_;
  SlabPartition slabs_;
  std::vector<Contact> scratch_;  // reused by partition_into_slabs
  SolverSettings settings_;
  PassObserver pass_observer_;
  double dt_;
  ContactDetector detector_;
  std::vector<Contact> contacts_;
  std::vector<Vec3> free_velocity_, end_velocity_;           // per contact, for contact_work
  std::unordered_map<std::uint64_t, ContactMemory> memory_;  // by contact key
};

}  // namespace dilatant
