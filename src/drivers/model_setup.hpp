#pragma once
// Turns the validated configuration into the engine's objects.
#include <memory>

#include "fluid/suspending_fluid.hpp"
#include "friction/friction_law.hpp"
#include "io/config.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant {

// eta_f in the simulation's units: the scene gives it directly, the shear cell
// derives it from lambda.
FrictionLaw make_friction_law(const FrictionConfig& friction, double eta_f);
SolverSettings make_solver_settings(const SolverConfig& solver);
// The fluid forces of [fluid] with viscosity eta_f (code units); null when
// neither drag nor lubrication is on (the literal model). Held by pointer: the
// stepper keeps its address, which must not move with the driver.
std::unique_ptr<SuspendingFluid> make_fluid(const FluidConfig& fluid, double eta_f);

}  // namespace dilatant
