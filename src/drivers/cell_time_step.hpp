#pragma once
// The shear cell's time step, chosen before each step (solver.dt = 0), and the
// fastest push-out of an overlap that goes with it (docs/model.md "Overlap
// push-out").
#include <optional>
#include <vector>

#include "boundary/drive.hpp"
#include "io/config.hpp"
#include "measure/flow_series.hpp"
#include "solver/local_problem.hpp"
#include "world/world.hpp"

namespace dilatant {

struct TimeStepChoice {
  double dt = 0.0;
  bool by_drive = false;  // the drive's bound, not the fastest body, set it
  double dt_drive = 0.0;  // the drive's bound alone (0 with a fixed solver.dt)
  // Fastest push-out of an overlap, c r_min / dt_drive (none with a fixed
  // solver.dt, whose step no speed can shorten).
  double max_push_out = kNoPushOutCap;
  // The flow the step's speeds were taken relative to (solver.step_frame =
  // "flow"; none in the lab frame): the detection margin takes it too.
  std::optional<ShearFlow> mean_flow;
};

// solver.dt if set; else no body may move more than c = solver.max_displacement
// times r_min in one step, neither at its current speed nor under the drive;
// in solver.step_frame's frame (the lab, or the drive's mean flow).
TimeStepChoice choose_time_step(const World& world, const Drive& drive, const SolverConfig& solver);

// The stress whose impulse on a particle's cross-section in one step,
// sigma_ref (2 R_max)^2 dt, is the unit of the solver's residual
// (SolverSettings::reference_impulse; docs/model.md "Convergence criterion"):
// the applied tau under stress control. Rate control applies none: there it is
// the last output row's measured |sigma_zx|, but at least the Bagnold stress
// rho_p (2 R_max gamma_dot)^2 of the imposed rate and the fluid's viscous
// stress eta_f gamma_dot (the first row, and a flow that has gone slack). The
// rows are in the checkpoint, so a resumed run takes the same unit.
double reference_stress(const CellConfig& cell, double density, double eta_f,
                        const std::vector<FlowRow>& rows);

}  // namespace dilatant
