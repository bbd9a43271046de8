#pragma once
// One Contact Dynamics time step (Moreau–Jean, theta = 1), in explicit stages:
//
//   1. predict    v_free = v + dt (g + F_ext/m)          (no contacts)
//   2. detect     contacts whose gap may close within the step (cell list)
//   3. warm start impulses of contacts that existed last step
//   4. solve      nonlinear Gauss–Seidel until the impulses converge
//   5. store      impulses for the next step's warm start
//   6. integrate  x += dt v   with the end-of-step velocities (implicit)
//
// Collisions are perfectly inelastic in the normal direction (zero restitution).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/friction_law.hpp"
#include "solver/contact_solver.hpp"
#include "world/world.hpp"

namespace dilatant {

struct StepReport {
  SolveReport solve;
  std::size_t contacts_detected = 0;
  std::size_t contacts_closed = 0;   // contacts carrying a normal impulse
  double kinetic_energy_free = 0.0;  // after prediction, before contacts act
  double kinetic_energy = 0.0;       // at the end of the step
  double max_overlap = 0.0;          // largest overlap at the end of the step
};

class TimeStepper {
 public:
  TimeStepper(FrictionLaw law, SolverSettings settings, double dt)
      : law_(std::move(law)), settings_(settings), dt_(dt) {}

  StepReport step(World& world);

  double dt() const { return dt_; }
  const FrictionLaw& law() const { return law_; }
  // Contacts of the last step with their impulses and friction regimes.
  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  double detection_margin(const World& world) const;
  void warm_start(Bodies& bodies);
  double largest_overlap(const World& world) const;

  FrictionLaw law_;
  SolverSettings settings_;
  double dt_;
  ContactDetector detector_;
  std::vector<Contact> contacts_;
  std::unordered_map<std::uint64_t, Vec3> last_impulse_;  // world-frame P by contact key
};

}  // namespace dilatant
