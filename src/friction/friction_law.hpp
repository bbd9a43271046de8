#pragma once
// The friction laws a contact can obey. A law is any type with
//     double mu(double s) const;
//     TangentialSolution solve(const TangentialProblem&) const;
// and joins the variant below. The solver dispatches once per sweep
// (std::visit outside the contact loop), so the per-contact call is inlined.
#include <variant>

#include "friction/coulomb_law.hpp"
#include "friction/stribeck_law.hpp"

namespace dilatant {

using FrictionLaw = std::variant<CoulombLaw, StribeckLaw>;

inline double friction_coefficient(const FrictionLaw& law, double s) {
  return std::visit([s](const auto& l) { return l.mu(s); }, law);
}

}  // namespace dilatant
