#include "drivers/cell_time_step.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant {

// Automatic time step (solver.dt = 0): no body may move more than
// c = solver.max_displacement (default 0.02) times r_min in one step, neither at
// its current speed nor under the drive (its own bound, Drive::time_step_bound;
// from rest under a force, sqrt(2 c r_min / a)):
//     dt = min(c r_min / v_max, dt_drive).
// An overlap left by an unconverged step is pushed out at |g|/dt, so a shorter
// step pushes it faster; the fastest body sets the next step, so past a point
// speed and step feed each other until the run blows up (a cold start at
// phi 0.64 did: docs/model.md "Overlap push-out"). The solver therefore pushes
// overlaps out no faster than c r_min / dt_drive: a push-out alone never asks
// for a step shorter than the drive's, whatever the step.
TimeStepChoice choose_time_step(const World& world, const Drive& drive,
                                const SolverConfig& solver) {
  if (solver.dt > 0.0) return {solver.dt, false};
  const Bodies& b = world.bodies;
  double v_max = 0.0, r_min = b.radius[0];
  for (std::size_t i = 0; i < b.size(); ++i) {
    v_max = std::max(v_max, b.velocity[i].norm() + b.radius[i] * b.angular_velocity[i].norm());
    r_min = std::min(r_min, b.radius[i]);
  }
  const double c = solver.max_displacement;
  const double dt_drive = drive.time_step_bound(world, c * r_min);
  const double dt_speed = v_max > 0.0 ? c * r_min / v_max : dt_drive;
  return {std::min(dt_drive, dt_speed), dt_drive <= dt_speed, dt_drive, c * r_min / dt_drive};
}

double reference_stress(const CellConfig& cell, double density, double eta_f,
                        const std::vector<FlowRow>& rows) {
  if (cell.control != ShearControl::Rate) return cell.shear_stress;
  const double gamma_dot = cell.shear_rate, diameter = 2.0 * cell.radius_max;
  const double bagnold = density * diameter * diameter * gamma_dot * gamma_dot;
  const double measured = rows.empty() ? 0.0 : std::abs(invariants(rows.back().stress).shear);
  return std::max({measured, bagnold, eta_f * gamma_dot});
}

}  // namespace dilatant
