#pragma once
// Turns the validated configuration into the engine's objects.
#include <memory>
#include <string>

#include "fluid/suspending_fluid.hpp"
#include "friction/friction_law.hpp"
#include "io/config.hpp"
#include "solver/contact_solver.hpp"
#include "world/world.hpp"

namespace dilatant {

// eta_f and the critical load in the simulation's units (Config::fluid_viscosity(),
// Config::critical_load()): the scene gives them directly, the shear cell
// derives them from lambda.
FrictionLaw make_friction_law(const FrictionConfig& friction, double eta_f, double critical_load);
// solver.threads, 0 (all) and beyond the machine's hardware threads alike,
// becomes at most hardware_threads(): more threads than cores make every
// sweep's barrier wait for a thread that is not running (on 2 cores, 4 / 16 /
// 1,024 threads took 31 / 21 / > 60 s where one took 0.3 s). Results do not
// depend on the count (solver/slab_partition.hpp).
SolverSettings make_solver_settings(const SolverConfig& solver);
int hardware_threads();
// The line that says solver.threads was capped; empty when it was not.
std::string thread_cap_warning(const SolverConfig& solver);

// "" unless `jobs` runs side by side with `threads_per_job` solver threads
// each ask for more threads than the machine has (a sweep); else one warning
// line: each point then runs slower than alone.
std::string oversubscription_warning(int jobs, int threads_per_job);
// The residual's unit in a world under gravity, as a force
// (TimeStepper::set_reference_force; docs/model.md "Convergence criterion"):
// the heaviest free body's weight, whose impulse in one step is what gravity
// puts on one grain. 0 without gravity: the solver then measures against the
// loaded contacts' RMS impulse.
double weight_force(const World& world);
// The fluid forces of [fluid] with viscosity eta_f (code units); null when
// neither drag nor lubrication is on (the literal model). Held by pointer: the
// stepper keeps its address, which must not move with the driver.
std::unique_ptr<SuspendingFluid> make_fluid(const FluidConfig& fluid, double eta_f);

}  // namespace dilatant
