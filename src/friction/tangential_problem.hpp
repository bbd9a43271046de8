#pragma once
// The tangential half of one contact's local problem, as the Gauss–Seidel solver
// hands it to a friction law (see solver/contact_solver.hpp for the derivation).
//
// With the other contacts frozen, the sliding velocity at the contact after the
// step is   u_t = u_t_free + w_t * P_t,   where u_t_free is the sliding velocity
// this contact would have without any tangential impulse and w_t is the
// tangential Delassus (inverse effective mass) coefficient. The law must find
// the impulse P_t = -|P_t| u_t_free/|u_t_free| that obeys it. Only magnitudes
// matter: friction opposes the free slip, and the sliding speed is
//     v_s = |u_t_free| - w_t |P_t|   (>= 0).
#include <cstdint>

namespace dilatant {

// Which branch of a law the solver imposes (Any: the law's own deterministic
// rule). KeepHydrodynamic: the contact slid on the HD branch in the previous
// step; it stays there while an HD answer with s >= s_c exists (see
// friction/stribeck_law.hpp for why), else the law's own rule applies.
// Boundary: the mu0 cone whatever s or the load; Frictionless: no friction
// whatever the load (the critical-load law's two statuses frozen,
// friction/critical_load_law.hpp).
enum class FrictionBranch : std::uint8_t {
  Any,
  Boundary,
  Hydrodynamic,
  KeepHydrodynamic,
  Frictionless
};

struct TangentialProblem {
  double free_slip = 0.0;       // |u_t_free|, sliding speed without friction impulse
  double compliance = 0.0;      // w_t, sliding speed removed per unit tangential impulse
  double normal_impulse = 0.0;  // p_n of this contact, already solved
  double dt = 0.0;              // time step: the normal force is N = p_n / dt
  double reduced_radius = 0.0;  // R_p of the Sommerfeld number
  FrictionBranch branch = FrictionBranch::Any;
  double slip_hint = 0.0;  // sliding speed of the last sweep, a start for root finding (0: none)
};

enum class Regime : std::uint8_t {
  Open,                // no normal force: no friction
  Stick,               // sliding speed 0, impulse inside the mu0 cone
  BoundaryLubricated,  // sliding with mu0 (s < s_c)
  Hydrodynamic,        // sliding with mu(s), s >= s_c
  Frictionless,        // loaded below the critical load: sliding without friction
};
// The last Regime, for readers of stored regimes (checkpoints).
inline constexpr Regime kLastRegime = Regime::Frictionless;

const char* regime_name(Regime r);  // "open", "stick", "bl", "hd", "frictionless"

struct TangentialSolution {
  double impulse = 0.0;        // |P_t|
  double sliding_speed = 0.0;  // v_s after the step
  double sommerfeld = 0.0;     // s (0 when sticking)
  Regime regime = Regime::Open;
};

}  // namespace dilatant
