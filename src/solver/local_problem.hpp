#pragma once
// One contact's local problem, the others frozen (derivation in
// solver/contact_solver.hpp): the exact impulse this contact would take given
// the current velocities. A Gauss–Seidel pass applies it contact after
// contact; the residual (solver/contact_residual.hpp) measures how far each
// contact's impulse still is from it.
#include <algorithm>
#include <limits>

#include "detection/contact.hpp"
#include "friction/tangential_problem.hpp"
#include "world/bodies.hpp"

namespace dilatant {

// Relative velocity of i's surface w.r.t. the partner's at the contact point.
inline Vec3 relative_velocity(const Contact& c, const Bodies& b) {
  Vec3 u = b.velocity[c.i] - c.arm_i * b.angular_velocity[c.i].cross(c.normal);
  if (!c.with_plane()) {
    u -= b.velocity[c.other] + c.arm_j * b.angular_velocity[c.other].cross(c.normal);
    u[0] -= c.image_drift;     // the partner's image across a Lees–Edwards boundary
    u[2] += c.dilation_drift;  // the box's affine dilation (pressure control)
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
// the last pass (the critical-load law's status too: frictional is the mu0
// cone, Boundary; below the threshold, Frictionless); before, the HD branch if
// it slid on it in the previous step.
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
    case Regime::Frictionless:
      return FrictionBranch::Frictionless;
    case Regime::Open:
      break;
  }
  return FrictionBranch::Any;
}

// The end-of-step normal velocity the contact asks for is u_n >= -g/dt: a gap
// g >= 0 may close exactly, an overlap (g < 0: left by an earlier step the
// solver ended before convergence) is pushed out at |g|/dt, but never faster
// than `max_push_out`. The cap is the "maximum penetration-correction velocity"
// of game-physics solvers (Catto, Box2D's contactPushMaxVelocity; Jolt's
// max_penetration_distance): without it the push-out grows as dt shrinks, and
// with an automatic step dt = c r_min / v_max it feeds the very speed that
// shortens the next step (docs/model.md "Overlap push-out"). It only acts on
// overlaps and only while |g| > dt max_push_out: a converged, overlap-free
// step never meets it; a capped overlap is removed over several steps.
inline constexpr double kNoPushOutCap = std::numeric_limits<double>::infinity();
inline double gap_rate(double gap, double inv_dt, double max_push_out) {
  return std::max(gap * inv_dt, -max_push_out);
}

// The round-off of recomputing contact c's impulse from the velocities of its
// bodies, 16 eps |v|_c / w_n with |v|_c = |v_i| + r_i |w_i| + |v_j| + r_j |w_j|:
// impulse changes below it are not progress (solver/contact_solver.hpp).
inline double round_off_impulse(const Contact& c, const Bodies& b) {
  double speed = b.velocity[c.i].norm() + c.arm_i * b.angular_velocity[c.i].norm();
  if (!c.with_plane())
    speed += b.velocity[c.other].norm() + c.arm_j * b.angular_velocity[c.other].norm();
  return 16.0 * std::numeric_limits<double>::epsilon() * speed / c.w_n;
}

struct LocalAnswer {
  double p_n = 0.0;
  Vec3 p_t = Vec3::Zero();
  double p_lub = 0.0;
  TangentialSolution tangential;
};

// The normal part of a pair with a squeeze film, k = c.lubrication (> 0), the
// other contacts frozen. Its impulse is p_lub = -k u_n+ (fluid/squeeze_film.hpp)
// and u_n+ = u_n_free + w_n (p_n + p_lub), so with the contact open (p_n = 0)
//     u_n+ = u_n_free / (1 + w_n k).
// If that keeps the gap open at the end of the step (g/dt + u_n+ >= 0, with
// rate = g/dt as gap_rate() caps it) it is the answer. Otherwise the surfaces
// touch: u_n+ = -g/dt, the film carries p_lub = k g/dt and the contact the rest,
//     p_n = (-g/dt - u_n_free) / w_n - k g/dt,
// which is > 0 exactly when the open answer failed (for g >= 0). A touching pair
// thus takes its film's resistance up to contact and Signorini's beyond: the
// hard-sphere limit of a film regularised by delta (no singularity at h = 0).
struct NormalAnswer {
  double p_n = 0.0;
  double p_lub = 0.0;
};
inline NormalAnswer solve_normal_with_film(double u_n_free, double rate, double w_n, double k) {
  const double u_open = u_n_free / (1.0 + w_n * k);
  if (rate + u_open >= 0.0) return {0.0, -k * u_open};
  const double u_touch = -rate;
  const double p_lub = -k * u_touch;
  return {std::max(0.0, (u_touch - u_n_free) / w_n - p_lub), p_lub};
}

// The local answer of contact c, over-relaxed in its normal part by `relaxation`
// (1: the exact local solution). The squeeze film's impulse is always exact.
// Overlaps are pushed out no faster than max_push_out (gap_rate()).
template <class Law>
inline LocalAnswer solve_local(const Contact& c, const Bodies& b, const Law& law, double dt,
                               double inv_dt, double relaxation, FrictionBranch branch,
                               double max_push_out = kNoPushOutCap) {
  const Vec3 u = relative_velocity(c, b);
  const double u_n = u.dot(c.normal);
  // Free velocities: remove this contact's own current impulses.
  const double u_n_free = u_n - c.w_n * (c.p_n + c.p_lub);
  const Vec3 u_t_free = (u - u_n * c.normal) - c.w_t * c.p_t;

  // Over-relaxed normal impulse (SOR); the fixed point is Gauss–Seidel's.
  LocalAnswer a;
  double p_n_exact;
  const double rate = gap_rate(c.gap, inv_dt, max_push_out);
  if (c.lubrication > 0.0) {
    const NormalAnswer n = solve_normal_with_film(u_n_free, rate, c.w_n, c.lubrication);
    p_n_exact = n.p_n;
    a.p_lub = n.p_lub;
  } else {
    p_n_exact = std::max(0.0, -(u_n_free + rate) / c.w_n);
  }
  a.p_n = std::max(0.0, c.p_n + relaxation * (p_n_exact - c.p_n));
  const double free_slip = u_t_free.norm();
  a.tangential = law.solve(
      TangentialProblem{free_slip, c.w_t, a.p_n, dt, c.reduced_radius, branch, c.sliding_speed});
  a.p_t = free_slip > 0.0 ? Vec3((-a.tangential.impulse / free_slip) * u_t_free) : Vec3::Zero();
  return a;
}

}  // namespace dilatant
