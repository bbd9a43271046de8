#pragma once
// Turns the validated configuration into the engine's objects.
#include "friction/friction_law.hpp"
#include "io/config.hpp"
#include "solver/contact_solver.hpp"

namespace dilatant {

// eta_f in the simulation's units: the scene gives it directly, the shear cell
// derives it from lambda.
FrictionLaw make_friction_law(const FrictionConfig& friction, double eta_f);
SolverSettings make_solver_settings(const SolverConfig& solver);

}  // namespace dilatant
