#pragma once
// Recognising the columns of a flow-curve table by name, and their units.
//
// A heading is a name and an optional unit: "Shear Rate [1/s]",
// "Viscosity (mPa·s)", "shear_stress", "eta / Pa s", "Shear Stress in Pa".
// Names are compared in lower case with '_', '-' and '.' read as spaces:
//   shear rate    shear rate, rate, strain rate, gamma dot, gammadot, gdot, γ̇
//   shear stress  shear stress, stress, tau, τ, sigma
//   viscosity     viscosity, apparent viscosity, shear viscosity,
//                 dynamic viscosity, visc, eta, η
// (complex viscosity, an oscillatory quantity, is not a viscosity here).
// Units, to SI (a heading without a unit is taken as SI, see docs/analysis.md):
//   shear rate    1/s, s^-1, s-1, /s, 1/sec
//   shear stress  Pa, mPa, kPa, MPa, dyn/cm2, dyn/cm^2
//   viscosity     Pa·s, mPa·s, kPa·s, cP, P   (any of "·", ".", "*", " " or
//                 nothing between Pa and s)
#include <optional>
#include <string>
#include <string_view>

namespace dilatant::analysis {

enum class Quantity { ShearRate, ShearStress, Viscosity };

// "shear rate", "shear stress", "viscosity": for messages.
std::string_view quantity_name(Quantity q);

struct Heading {
  std::optional<Quantity> quantity;  // nullopt: not a flow-curve column
  std::string unit;                  // as written, "" when none
};

// Splits a heading into name and unit and recognises the name.
Heading parse_heading(std::string_view heading);

// A column whose text names each row's step: Malvern rSpace's "Action Name",
// "Step name", "Step".
bool names_step_column(std::string_view heading);

// The unit of a units row's field: "[Pa·s]" -> "Pa·s".
std::string unit_of_units_field(std::string_view field);

// The factor that converts a value in `unit` to SI; nullopt for an unknown unit.
// An empty unit gives 1.
std::optional<double> si_factor(Quantity q, std::string_view unit);

// The known units of a quantity, for messages: "1/s, s^-1, ...".
std::string_view known_units(Quantity q);

}  // namespace dilatant::analysis
