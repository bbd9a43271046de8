#include "solver/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dilatant {

namespace {

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

template <class Law>
SweepChange sweep(std::vector<Contact>& contacts, Bodies& b, const Law& law, double dt) {
  SweepChange change;
  const double inv_dt = 1.0 / dt;
  for (Contact& c : contacts) {
    const Vec3 u = relative_velocity(c, b);
    const double u_n = u.dot(c.normal);
    // Free velocities: remove this contact's own current impulse.
    const double u_n_free = u_n - c.w_n * c.p_n;
    const Vec3 u_t_free = (u - u_n * c.normal) - c.w_t * c.p_t;

    const double p_n = std::max(0.0, -(u_n_free + c.gap * inv_dt) / c.w_n);
    const double free_slip = u_t_free.norm();
    const TangentialSolution t =
        law.solve(TangentialProblem{free_slip, c.w_t, p_n, dt, c.reduced_radius});
    const Vec3 p_t = free_slip > 0.0 ? Vec3((-t.impulse / free_slip) * u_t_free) : Vec3::Zero();

    const Vec3 dp = (p_n - c.p_n) * c.normal + (p_t - c.p_t);
    apply_impulse(c, dp, b);
    c.p_n = p_n;
    c.p_t = p_t;
    c.sliding_speed = t.sliding_speed;
    c.sommerfeld = t.sommerfeld;
    c.regime = t.regime;
    change.change_squared += dp.squaredNorm();
    change.impulse_squared += p_n * p_n + p_t.squaredNorm();
  }
  return change;
}

}  // namespace

void apply_impulses(const std::vector<Contact>& contacts, Bodies& bodies) {
  for (const Contact& c : contacts) apply_impulse(c, c.p_n * c.normal + c.p_t, bodies);
}

SweepChange gauss_seidel_sweep(std::vector<Contact>& contacts, Bodies& bodies,
                               const FrictionLaw& law, double dt) {
  return std::visit([&](const auto& l) { return sweep(contacts, bodies, l, dt); }, law);
}

SolveReport solve_contacts(std::vector<Contact>& contacts, Bodies& bodies, const FrictionLaw& law,
                           double dt, const SolverSettings& settings) {
  SolveReport report;
  report.converged = false;
  if (contacts.empty()) {
    report.converged = true;
    return report;
  }
  // Round-off floor of a sweep's impulse changes (see the header).
  double noise_squared = 0.0;
  for (const Contact& c : contacts) {
    double speed = bodies.velocity[c.i].norm() + c.arm_i * bodies.angular_velocity[c.i].norm();
    if (!c.with_plane()) {
      speed += bodies.velocity[c.other].norm() + c.arm_j * bodies.angular_velocity[c.other].norm();
    }
    const double noise = 16.0 * std::numeric_limits<double>::epsilon() * speed / c.w_n;
    noise_squared += noise * noise;
  }
  std::visit(
      [&](const auto& l) {
        while (report.iterations < settings.max_iterations) {
          const SweepChange ch = sweep(contacts, bodies, l, dt);
          ++report.iterations;
          const double change_squared = std::max(0.0, ch.change_squared - noise_squared);
          report.residual = ch.impulse_squared > 0.0
                                ? std::sqrt(change_squared / ch.impulse_squared)
                                : (change_squared > 0.0 ? 1.0 : 0.0);
          if (report.residual <= settings.tolerance) {
            report.converged = true;
            break;
          }
        }
      },
      law);
  return report;
}

}  // namespace dilatant
