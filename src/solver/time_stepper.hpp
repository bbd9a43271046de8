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
// With SolverSettings::redo_unconverged no step is accepted unconverged
// (docs/model.md "Unconverged steps"): once a driver has set the shortest
// step (set_shortest_dt()), a solve that ends above the tolerance is undone (the bodies' velocities
// and the boundary's state as they were before stage 1) and stages 1-4 are redone at half the step,
// warm-started from the same memory scaled to the shorter step. Below the shortest step the stepper
// throws SolveFailure, naming where. The step taken is StepReport::dt; the driver's clock and
// strain advance by it.
//
// Collisions are perfectly inelastic in the normal direction (zero restitution).
// The stepper knows no particular cell: a boundary and fluid forces are given
// to it (both optional; without them it integrates a plain granular world).
#include <cstdint>
#include <optional>
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
#include "world/shear_flow.hpp"
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
  // The step taken: dt(), or dt() / 2^redos after redos.
  double dt = 0.0;
  int redos = 0;
  // The solve work of the attempts that were undone, in sweep-equivalents
  // (their contact visits over their contacts detected): work spent all the same.
  double redone_sweep_equivalents = 0.0;
};

// A state the step cannot continue from (a non-finite body). Drivers add the
// step and strain to the message and stop the run.
class NumericalFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A step whose contact solve did not converge even at the shortest step the
// driver allows: never accepted, the run stops (exit 1; a sweep records the
// point as failed). The message names the time, the step, the residual and
// the two bodies (by id) of the worst contact.
class SolveFailure : public NumericalFault {
 public:
  using NumericalFault::NumericalFault;
};

// What the drivers allow a redo: down to 1/64 of their step's bound, six
// halvings (docs/model.md "Unconverged steps").
inline constexpr double kShortestStepDivisor = 64.0;

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
  // The shortest step a redo may take (see the top of this file); 0, the
  // default, accepts an unconverged step as it is (and StepReport says so),
  // as does SolverSettings::redo_unconverged = false.
  void set_shortest_dt(double dt) { shortest_dt_ = dt; }
  // Called after every pass of the solve (solver/contact_problem.hpp); empty: none.
  void set_pass_observer(PassObserver observer) { pass_observer_ = std::move(observer); }
  // The mean flow the driver's step bounds speeds relative to (its detection
  // margin then does too); none: the lab frame.
  void set_mean_flow(std::optional<ShearFlow> flow) { mean_flow_ = flow; }
  // The solver's cap on the push-out speed of overlaps (SolverSettings).
  void set_max_push_out(double speed) { settings_.max_push_out = speed; }
  // The residual's unit for the next steps, as a force (the driver's, from the
  // load it applies): SolverSettings::reference_impulse is this force times
  // the step being solved, halved with it on a redo. 0: none (the loaded
  // contacts' RMS impulse).
  void set_reference_force(double force) { reference_force_ = force; }
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
  // Stages 1-4 at dt_, adding to report (its times accumulate over redos).
  void predict_detect_solve(World& world, Boundary* boundary, double warm_scale,
                            StepReport& report);
  // The SolveFailure of a step that failed at the shortest step.
  [[noreturn]] void fail(const World& world, const StepReport& report) const;
  double detection_margin(const World& world) const;
  void warm_start(Bodies& bodies, double scale);
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
  double shortest_dt_ = 0.0;
  double reference_force_ = 0.0;
  std::optional<ShearFlow> mean_flow_;
  // Velocities and spins before stage 1, for a redo.
  std::vector<Vec3> saved_velocity_, saved_angular_velocity_;
  ContactDetector detector_;
  std::vector<Contact> contacts_;
  std::vector<Vec3> free_velocity_, end_velocity_;           // per contact, for contact_work
  std::unordered_map<std::uint64_t, ContactMemory> memory_;  // by contact key
};

}  // namespace dilatant
