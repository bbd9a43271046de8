#pragma once
// One contact's local problem, the others frozen (derivation in
// solver/contact_solver.hpp): the exact impulse this contact would take given
// the current velocities. The Gauss–Seidel sweep applies it contact after
// contact; the residual (solver/contact_residual.hpp) measures how far each
// contact's impulse still is from it.
#include <algorithm>

#include "detection/contact.hpp"
#include "friction/tangential_problem.hpp"
#include "world/bodies.hpp"

namespace dilatant {

// Relative velocity of i's surface w.r.t. the partner's at the contact point.
inline Vec3 relative_velocity(const Contact& c, const Bodies& b) {
  Vec3 u = b.velocity[c.i] - c.arm_i * b.angular_velocity[c.i].cross(c.normal);
  if (!c.with_plane()) {
    u -= b.velocity[c.other] + c.arm_j * b.angular_velocity[c.other].cross(c.normal);
  }
  return u;
}

// Applies impulse dp to i and -dp to the partner, at their contact points.
inline void apply_impulse(const Contact& c, const Vec3& dp, Bodies& b) {
  const Vec3 n_x_dp = c.normal.cross(dp);
  b.velocity[c.i] += b.inv_mass[c.i] * dp;
  b.angular_velocity[c.i] -= (b.inv_inertia[c.i] * c.arm_i) * n_x_dp;
  if (!c.with_plane()) {
    b.velocity[c.other] -= b.inv_mass[c.other] * dp;
    b.angular_velocity[c.other] -= (b.inv_inertia[c.other] * c.arm_j) * n_x_dp;
  }
}

// The branch imposed on a contact: once branches are frozen, the one it took in
// the last sweep; before, the HD branch if it slid on it in the previous step.
inline FrictionBranch imposed_branch(const Contact& c, bool frozen) {
  if (!frozen) {
    return c.previous_regime == Regime::Hydrodynamic ? FrictionBranch::KeepHydrodynamic
                                                     : FrictionBranch::Any;
  }
  switch (c.regime) {
    case Regime::Stick:
    case Regime::BoundaryLubricated:
      return FrictionBranch::Boundary;
    case Regime::Hydrodynamic:
      return FrictionBranch::Hydrodynamic;
    case Regime::Open:
      break;
  }
  return FrictionBranch::Any;
}

struct LocalAnswer {
  double p_n = 0.0;
  Vec3 p_t = Vec3::Zero();
  TangentialSolution tangential;
};

// The local answer of contact c, over-relaxed in its normal part by `relaxation`
// (1: the exact local solution).
template <class Law>
inline LocalAnswer solve_local(const Contact& c, const Bodies& b, const Law& law, double dt,
                               double inv_dt, double relaxation, FrictionBranch branch) {
  const Vec3 u = relative_velocity(c, b);
  const double u_n = u.dot(c.normal);
  // Free velocities: remove this contact's own current impulse.
  const double u_n_free = u_n - c.w_n * c.p_n;
  const Vec3 u_t_free = (u - u_n * c.normal) - c.w_t * c.p_t;

  // Over-relaxed normal impulse (SOR); the fixed point is Gauss–Seidel's.
  LocalAnswer a;
  const double p_n_exact = std::max(0.0, -(u_n_free + c.gap * inv_dt) / c.w_n);
  a.p_n = std::max(0.0, c.p_n + relaxation * (p_n_exact - c.p_n));
  const double free_slip = u_t_free.norm();
  a.tangential = law.solve(
      TangentialProblem{free_slip, c.w_t, a.p_n, dt, c.reduced_radius, branch, c.sliding_speed});
  a.p_t = free_slip > 0.0 ? Vec3((-a.tangential.impulse / free_slip) * u_t_free) : Vec3::Zero();
  return a;
}

}  // namespace dilatant
