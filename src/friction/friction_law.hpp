#pragma once
// The friction laws a contact can obey. A law is any type with
//     TangentialSolution solve(const TangentialProblem&) const;
// and joins the variant below. The solver dispatches once per sweep
// (std::visit outside the contact loop), so the per-contact call is inlined.
#include <type_traits>
#include <variant>

#include "friction/coulomb_law.hpp"
#include "friction/critical_load_law.hpp"
#include "friction/stribeck_law.hpp"

namespace dilatant {

using FrictionLaw = std::variant<CoulombLaw, StribeckLaw, CriticalLoadLaw>;

// The friction coefficient of a sliding contact at Sommerfeld number s that
// carries the normal force N: the Coulomb and Stribeck laws read s, the
// critical-load law reads N.
inline double friction_coefficient(const FrictionLaw& law, double s, double normal_force) {
  return std::visit(
      [s, normal_force](const auto& l) {
        if constexpr (std::is_same_v<std::decay_t<decltype(l)>, CriticalLoadLaw>)
          return l.mu_at_load(normal_force);
        else
          return l.mu(s);
      },
      law);
}

}  // namespace dilatant
