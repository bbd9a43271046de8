#include "drivers/cell_time_step.hpp"

#include <algorithm>
#include <cmath>

namespace dilatant {

// Automatic time step (solver.dt = 0): no body may move more than
// c = solver.max_displacement (default 0.02) times r_min in one step, neither at
// its current speed nor under the drive (its own bound, Drive::time_step_bound;
// from rest under a force, sqrt(2 c r_min / a)):
//     dt = min(c r_min / v_max, dt_drive).
// In the lab frame (solver.step_frame = "lab", before 0.8) v_max is the
// largest |v| + r |omega|. But the contact geometry changes with the speed of
// a body relative to its neighbours, and in a shear flow the absolute speed
// grows with the height: gamma_dot Lz / 2 at the top of a Lees–Edwards box, the
// wall's V in a wall cell. The steps per strain then grew with the cell (10,
// 16, 25 R boxes: 685, 1,028, 1,562; bench/RESULTS.md). In the flow frame
// ("flow") the speed is taken relative to the drive's mean flow u(z)
// (Drive::mean_flow), and the flow's own shear between neighbours is bounded
// apart:
//     v_max = max_i (|v_i - u(z_i)| + r_i |omega_i|) + |gamma_dot| R_max,
// with the drive's bound taken over a span R_max instead of the box: two
// neighbours then move relative to each other by at most 2 c r_min from their
// fluctuations plus 2 c r_min from the mean shear, as in the lab frame, in
// steps that no longer depend on the height.
// An overlap left by an unconverged step is pushed out at |g|/dt, so a shorter
// step pushes it faster; the fastest body sets the next step, so past a point
// speed and step feed each other until the run blows up (a cold start at
// phi 0.64 did: docs/model.md "Overlap push-out"). The solver therefore pushes
// overlaps out no faster than c r_min / dt_drive: a push-out alone never asks
// for a step shorter than the drive's, whatever the step.
TimeStepChoice choose_time_step(const World& world, const Drive& drive,
                                const SolverConfig& solver) {
  if (solver.dt > 0.0) return {.dt = solver.dt, .mean_flow = std::nullopt};
  const Bodies& b = world.bodies;
  const bool in_flow = solver.step_frame == StepFrame::MeanFlow;
  const ShearFlow flow = in_flow ? drive.mean_flow(world) : ShearFlow{};
  double v_max = 0.0, r_min = b.radius[0], r_max = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    Vec3 v = b.velocity[i];
    v[0] -= flow.shear_rate * (b.position[i][2] - flow.z0);
    v_max = std::max(v_max, v.norm() + b.radius[i] * b.angular_velocity[i].norm());
    r_min = std::min(r_min, b.radius[i]);
    r_max = std::max(r_max, b.radius[i]);
  }
  v_max += std::abs(flow.shear_rate) * r_max;
  const double c = solver.max_displacement;
  const double span = in_flow ? r_max : world.box.length[2];
  const double dt_drive = drive.time_step_bound(world, c * r_min, span);
  const double dt_speed = v_max > 0.0 ? c * r_min / v_max : dt_drive;
  return {.dt = std::min(dt_drive, dt_speed),
          .by_drive = dt_drive <= dt_speed,
          .dt_drive = dt_drive,
          .max_push_out = c * r_min / dt_drive,
          .mean_flow = in_flow ? std::optional<ShearFlow>(flow) : std::nullopt};
}

double reference_stress(const CellConfig& cell, double density, double eta_f,
                        const std::vector<FlowRow>& rows) {
  if (cell.control == ShearControl::Stress) return cell.shear_stress;
  const double gamma_dot = cell.shear_rate, diameter = 2.0 * cell.radius_max;
  const double bagnold = density * diameter * diameter * gamma_dot * gamma_dot;
  const double measured = rows.empty() ? 0.0 : std::abs(invariants(rows.back().stress).shear);
  // Under pressure control the normal stress imposed is a stress of the flow too.
  return std::max({measured, bagnold, eta_f * gamma_dot, cell.normal_stress});
}

}  // namespace dilatant
