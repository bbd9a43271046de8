// A static vertical column of N equal spheres resting on a plane under gravity.
//
// Closed form: the k-th contact from the top carries k m g (the plane carries
// N m g), and nothing moves.
//
// What the scheme should give, and how far off it may be.
// Every contact is active, so each step's local problems form the linear system
// W P = b (W the normal Delassus matrix of the chain, b = -(u_free + gap/dt)).
// Gauss–Seidel with W = L + D + U has the iteration matrix G = -(L + D)^-1 U;
// the error left when it stops is e = G (1 - G)^-1 d, d the last sweep's change,
// and the solver stops when |d| <= tol |P|. So the solver error of one step is
//     |delta| <= kappa tol |P|,   kappa = || G (1 - G)^-1 ||_2
// (kappa ~ 44 for N = 10: the chain is the slowest case for Gauss–Seidel).
// The error feeds into later steps: it leaves an end-of-step relative velocity
// W delta_{n-1} and a gap dt W delta_{n-1}, which the next step removes. Solving
// the recursion gives the impulses of step n as the static ones plus a second
// difference of solver errors,
//     P_n - P_static = delta_n - 2 delta_{n-1} + delta_{n-2},
// hence   |F_n - F_static| <= 4 kappa tol |F_static|        (every step),
//         |mean_n F_n - F_static| <= 2 kappa tol |F_static| / n_steps   (telescoping),
//         |gap_c| <= dt ||W|| kappa tol |P|,  so the drift of any sphere, a sum of
//         at most N gaps, is <= sqrt(N) dt ||W|| kappa tol |P|, at every step: the
//         gaps are corrected each step, they do not accumulate.
// kappa and ||W|| are computed below from the solver's own contact list.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::column_test {
namespace {

constexpr int kN = 10;
constexpr double kR = 0.5;
constexpr double kG = 9.81;
constexpr double kDt = 1e-3;
constexpr int kSteps = 2000;

// Static load of a contact: the plane carries N m g; the contact between
// spheres k-1 and k (counted from the bottom) carries (N - k) m g.
double static_load(const Contact& c, double m) {
  const int k = c.with_plane() ? 0 : std::max(c.i, c.other);
  return (kN - k) * m * kG;
}

struct GaussSeidelBounds {
  double kappa;   // || G (1 - G)^-1 ||_2
  double norm_w;  // || W ||_2
};

// The normal Delassus matrix of the contacts in the solver's order, and the
// error amplification of Gauss–Seidel on it.
GaussSeidelBounds gauss_seidel_bounds(const std::vector<Contact>& contacts, const Bodies& b) {
  const auto nc = static_cast<Eigen::Index>(contacts.size());
  const auto nb = static_cast<Eigen::Index>(b.size());
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(nc, 3 * nb);  // u_n = H v
  Eigen::VectorXd inv_m(3 * nb);
  for (Eigen::Index k = 0; k < nb; ++k) inv_m.segment<3>(3 * k).setConstant(b.inv_mass[k]);
  for (Eigen::Index c = 0; c < nc; ++c) {
    const Contact& ct = contacts[static_cast<std::size_t>(c)];
    h.block<1, 3>(c, 3 * ct.i) = ct.normal.transpose();
    if (!ct.with_plane()) h.block<1, 3>(c, 3 * ct.other) = -ct.normal.transpose();
  }
  const Eigen::MatrixXd w = h * inv_m.asDiagonal() * h.transpose();
  const Eigen::MatrixXd lower = w.triangularView<Eigen::Lower>();
  const Eigen::MatrixXd upper = w.triangularView<Eigen::StrictlyUpper>();
  const Eigen::MatrixXd g = -lower.inverse() * upper;
  const Eigen::MatrixXd one = Eigen::MatrixXd::Identity(nc, nc);
  const Eigen::MatrixXd amplification = g * (one - g).inverse();
  return {Eigen::JacobiSVD<Eigen::MatrixXd>(amplification).singularValues()(0),
          Eigen::JacobiSVD<Eigen::MatrixXd>(w).singularValues()(0)};
}

TEST(Column, ContactsCarryTheWeightAboveAndNothingDrifts) {
  World world = scenes::world_with_plane(Vec3(0.0, 0.0, -kG));
  for (int k = 0; k < kN; ++k) {
    world.bodies.add_sphere(k, Vec3(0.0, 0.0, kR + 2.0 * kR * k), kR, 1.0, false);
  }
  const double m = world.bodies.mass(0);
  const SolverSettings settings{};  // tolerance 1e-6
  TimeStepper stepper(CoulombLaw{0.3, 0.0}, settings, kDt);

  double static_norm = 0.0;  // |F_static|
  for (int k = 1; k <= kN; ++k) static_norm += (k * m * kG) * (k * m * kG);
  static_norm = std::sqrt(static_norm);

  std::vector<double> mean_force(kN, 0.0);  // by contact position in the list
  GaussSeidelBounds bounds{0.0, 0.0};
  double max_rel_error = 0.0, max_drift = 0.0;
  for (int n = 0; n < kSteps; ++n) {
    const StepReport report = stepper.step(world);
    ASSERT_TRUE(report.solve.converged) << "step " << n;
    const std::vector<Contact>& contacts = stepper.contacts();
    ASSERT_EQ(contacts.size(), static_cast<std::size_t>(kN)) << "step " << n;
    if (n == 0) bounds = gauss_seidel_bounds(contacts, world.bodies);
    double error_squared = 0.0;
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      const double force = contacts[c].p_n / kDt;
      const double e = force - static_load(contacts[c], m);
      error_squared += e * e;
      mean_force[c] += force / kSteps;
    }
    max_rel_error = std::max(max_rel_error, std::sqrt(error_squared) / static_norm);
    for (int k = 0; k < kN; ++k) {
      const Vec3 start(0.0, 0.0, kR + 2.0 * kR * k);
      max_drift = std::max(max_drift, (world.bodies.position[k] - start).norm());
    }
  }

  const double tol = settings.tolerance;
  const double p_norm = static_norm * kDt;
  const double force_bound = 4.0 * bounds.kappa * tol;
  const double mean_bound = 2.0 * bounds.kappa * tol / kSteps;
  const double drift_bound =
      std::sqrt(double(kN)) * kDt * bounds.norm_w * bounds.kappa * tol * p_norm;

  double mean_error_squared = 0.0;
  for (std::size_t c = 0; c < stepper.contacts().size(); ++c) {
    const double e = mean_force[c] - static_load(stepper.contacts()[c], m);
    mean_error_squared += e * e;
  }
  const double mean_rel_error = std::sqrt(mean_error_squared) / static_norm;

  scenes::record("kappa", bounds.kappa);
  scenes::record("force_rel_error", max_rel_error);
  scenes::record("force_rel_bound", force_bound);
  scenes::record("mean_force_rel_error", mean_rel_error);
  scenes::record("mean_force_rel_bound", mean_bound);
  scenes::record("drift", max_drift);
  scenes::record("drift_bound", drift_bound);
  EXPECT_LE(max_rel_error, force_bound);
  EXPECT_LE(mean_rel_error, mean_bound);
  EXPECT_LE(max_drift, drift_bound);
}

}  // namespace
}  // namespace dilatant::column_test
