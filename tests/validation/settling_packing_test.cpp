// A random loose packing of polydisperse frictional spheres settling under
// gravity: periodic in x and y, on a rough floor of glued (fixed) spheres.
//
// There is no closed form for the trajectory; what must hold are the energy and
// volume-exclusion properties of the scheme, each with a bound that follows
// from the solver's own stopping test.
//
// Energy. Let v_free be the velocities after the gravity prediction, P the
// contact impulses (normal and tangential, one 3-vector per contact) and
// W = H M^-1 H^T the Delassus matrix (u = H v are the contact velocities). Then
// exactly
//     KE_end - KE_free = P . u_end - 1/2 P^T W P,       (1/2 P^T W P >= 0)
// and u_end = u* + du, u* being each contact's velocity right after its last
// local solve. For that u*: p_n u*_n = -p_n gap/dt when p_n > 0 (Signorini) and
// p_t . u*_t = -|p_t| v_s <= 0 (friction opposes slip). du is what contacts
// solved later in the last sweep changed: |du| <= ||W|| |dP|, with
// |dP|^2 <= residual^2 |P|^2 + noise^2 the last sweep's change (the solver's
// stopping test; noise is its round-off floor, see contact_solver.hpp). So
//     P . u_end <= E_push + E_solver,
//         E_push   = sum_c p_n max(0, -gap) / dt   (overlaps pushed out at -gap/dt:
//                                                    the only source of energy),
//         E_solver = |P| ||W|| |dP|                (unconverged remainder),
// and KE_end <= KE_free + E_push + E_solver. ||W|| is bounded by Gershgorin over
// 3x3 blocks: a block W_cc' of two contacts sharing body b has norm
// <= 1/m_b + r_b^2/I_b, so ||W|| <= max_c sum_{b in c} deg_b (1/m_b + r_b^2/I_b).
//
// Overlap. The solve makes gap + dt u*_n >= 0 for every contact; the true
// end-of-step distance of two spheres is |d + dt dv| >= |d| + dt dv.n (and equal
// for a plane), so the end-of-step overlap is at most dt |du| <= dt ||W|| |dP|,
// plus the rounding of positions, a few eps |x|.
//
// Rest. The system must come to rest. Each step gravity gives every sphere the
// speed g dt (KE_free ~ 1/2 M (g dt)^2 at rest) and a resting packing takes it
// back: what remains at the end of the step is the unconverged remainder, of
// relative order tol times the Gauss–Seidel amplification (~1e-2 here, at
// tol = 1e-3). We call the packing at rest when the end-of-step speeds are
// below a tenth of g dt in the mean, KE_end <= 1e-2 KE_free, and the kinetic
// energy has fallen by six decades from its peak (~ M g h, the fall).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"
#include "validation/scene_helpers.hpp"

namespace dilatant::settling_packing_test {
namespace {

using scenes::kEps;

constexpr int kMobile = 200;
constexpr double kL = 16.0;      // periodic box length in x and y
constexpr double kHeight = 7.0;  // initial layer of mobile spheres, above the floor
constexpr double kFloorR = 0.9;  // glued floor spheres on a square grid of pitch 2
constexpr double kG = 1.0;
constexpr double kDt = 0.05;  // large on purpose: CD is implicit; settling only
constexpr int kSteps = 400;

World make_loose_packing() {
  World world;
  world.gravity = Vec3(0.0, 0.0, -kG);
  world.box.length = Vec3(kL, kL, 0.0);
  world.box.periodic = {true, true, false};
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Rough floor: holes between grid spheres are narrower than the smallest
  // mobile sphere (sqrt(2) - 0.9 = 0.51 < 0.8), so nothing falls through.
  const int n_floor = static_cast<int>(kL / 2.0);
  const double pitch = kL / n_floor;
  for (int a = 0; a < n_floor; ++a) {
    for (int b = 0; b < n_floor; ++b) {
      world.bodies.add_sphere(-1 - (a * n_floor + b),
                              Vec3((a + 0.5) * pitch, (b + 0.5) * pitch, 0.0), kFloorR, 1.0, true);
    }
  }
  // Mobile spheres, radii uniform in [0.8, 1], placed by random sequential
  // addition (largest first) without overlap in a slab above the floor.
  std::vector<double> radii(kMobile);
  for (double& r : radii) r = 0.8 + 0.2 * uniform(rng);
  std::sort(radii.begin(), radii.end(), std::greater<>());
  for (int k = 0; k < kMobile; ++k) {
    const double r = radii[static_cast<std::size_t>(k)];
    for (;;) {
      // Sequenced draws (argument order is unspecified; g++ drew z, y, x).
      const double uz = uniform(rng);
      const double uy = uniform(rng);
      const double ux = uniform(rng);
      const Vec3 x(kL * ux, kL * uy, 2.0 * kFloorR + r + (kHeight - 2.0 * r) * uz);
      bool free = true;
      for (std::size_t j = 0; j < world.bodies.size() && free; ++j) {
        free = world.box.minimum_image(x, world.bodies.position[j]).norm() >
               r + world.bodies.radius[j];
      }
      if (free) {
        world.bodies.add_sphere(k, x, r, 1.0, false);
        break;
      }
    }
  }
  return world;
}

struct EnergyTerms {
  double push = 0.0;           // E_push
  double solver = 0.0;         // E_solver
  double dp_norm = 0.0;        // |dP| bound
  double norm_w = 0.0;         // Gershgorin bound of ||W||
  double contact_power = 0.0;  // P . u_end
};

double speed_scale(const Contact& c, const Bodies& b) {
  double s = b.velocity[c.i].norm() + c.arm_i * b.angular_velocity[c.i].norm();
  if (!c.with_plane()) {
    s += b.velocity[c.other].norm() + c.arm_j * b.angular_velocity[c.other].norm();
  }
  return s;
}

EnergyTerms energy_terms(const std::vector<Contact>& contacts, const Bodies& b,
                         const std::vector<double>& start_speed_squared_by_contact,
                         double residual) {
  EnergyTerms e;
  std::vector<int> degree(b.size(), 0);
  for (const Contact& c : contacts) {
    ++degree[c.i];
    if (!c.with_plane()) ++degree[c.other];
  }
  auto block = [&](std::size_t k) {
    return b.inv_mass[k] + b.radius[k] * b.radius[k] * b.inv_inertia[k];
  };
  double p_squared = 0.0, noise_squared = 0.0;
  for (std::size_t n = 0; n < contacts.size(); ++n) {
    const Contact& c = contacts[n];
    double row = degree[c.i] * block(c.i);
    if (!c.with_plane()) row += degree[c.other] * block(c.other);
    e.norm_w = std::max(e.norm_w, row);
    p_squared += c.p_n * c.p_n + c.p_t.squaredNorm();
    e.push += c.p_n * std::max(0.0, -c.gap) / kDt;
    // The solver's noise floor, from the larger of the start and end speeds
    // (it uses the speeds at the start of its sweeps), doubled for safety.
    const double speed = std::max(std::sqrt(start_speed_squared_by_contact[n]), speed_scale(c, b));
    const double noise = 2.0 * 16.0 * kEps * speed / c.w_n;
    noise_squared += noise * noise;
    // P . u_end with the contact's own normal and arms (those of the solve).
    Vec3 u = b.velocity[c.i] - c.arm_i * b.angular_velocity[c.i].cross(c.normal);
    if (!c.with_plane()) {
      u -= b.velocity[c.other] + c.arm_j * b.angular_velocity[c.other].cross(c.normal);
    }
    e.contact_power += (c.p_n * c.normal + c.p_t).dot(u);
  }
  const double p_norm = std::sqrt(p_squared);
  e.dp_norm = std::sqrt(residual * residual * p_squared + noise_squared);
  e.solver = p_norm * e.norm_w * e.dp_norm;
  return e;
}

TEST(SettlingPacking, NoEnergyCreatedNoOverlapComesToRest) {
  World world = make_loose_packing();
  const SolverSettings settings{.tolerance = 1e-3, .max_iterations = 200};
  TimeStepper stepper(CoulombLaw{0.3, 0.0}, settings, kDt);

  double ke_peak = 0.0, worst_energy_margin = -1.0, worst_power_margin = -1.0;
  double worst_overlap_margin = -1.0, max_overlap = 0.0, max_push = 0.0;
  double max_gain = -std::numeric_limits<double>::infinity();
  double max_solver_term = 0.0;
  StepReport last;
  for (int n = 0; n < kSteps; ++n) {
    // Speeds before the step plus g dt bound the speeds the solver starts from.
    std::vector<double> start_speed(world.bodies.size());
    for (std::size_t k = 0; k < world.bodies.size(); ++k) {
      start_speed[k] = world.bodies.velocity[k].norm() + kG * kDt +
                       world.bodies.radius[k] * world.bodies.angular_velocity[k].norm();
    }
    const StepReport report = stepper.step(world);
    last = report;
    const std::vector<Contact>& contacts = stepper.contacts();
    std::vector<double> start_speed_squared(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      double s = start_speed[contacts[c].i];
      if (!contacts[c].with_plane()) s += start_speed[contacts[c].other];
      start_speed_squared[c] = s * s;
    }
    const EnergyTerms e =
        energy_terms(contacts, world.bodies, start_speed_squared, report.solve.residual);
    // Round-off of the energies: sums of a few hundred terms, n eps KE.
    const double roundoff =
        4.0 * static_cast<double>(world.bodies.size()) * kEps * report.kinetic_energy_free;
    const double gain = report.kinetic_energy - report.kinetic_energy_free;
    const double allowance = e.push + e.solver + roundoff;
    worst_energy_margin = std::max(worst_energy_margin, gain / allowance);
    worst_power_margin = std::max(worst_power_margin, e.contact_power / allowance);
    EXPECT_LE(gain, allowance) << "step " << n;
    EXPECT_LE(e.contact_power, allowance) << "step " << n;

    const double overlap_bound = kDt * e.norm_w * e.dp_norm + 8.0 * kEps * kL;
    worst_overlap_margin = std::max(worst_overlap_margin, report.max_overlap / overlap_bound);
    EXPECT_LE(report.max_overlap, overlap_bound) << "step " << n;

    ke_peak = std::max(ke_peak, report.kinetic_energy);
    max_overlap = std::max(max_overlap, report.max_overlap);
    max_gain = std::max(max_gain, gain);
    max_push = std::max(max_push, e.push);
    max_solver_term = std::max(max_solver_term, e.solver);
  }

  const double ke_end = last.kinetic_energy;
  double v_max = 0.0;
  for (std::size_t k = 0; k < world.bodies.size(); ++k) {
    v_max = std::max(v_max, world.bodies.velocity[k].norm());
  }
  scenes::record("max_ke_gain", max_gain);
  scenes::record("max_push_energy", max_push);
  scenes::record("max_solver_energy_term", max_solver_term);
  scenes::record("worst_gain_over_allowance", worst_energy_margin);
  scenes::record("worst_contact_power_over_allowance", worst_power_margin);
  scenes::record("max_overlap", max_overlap);
  scenes::record("worst_overlap_over_bound", worst_overlap_margin);
  scenes::record("ke_peak", ke_peak);
  scenes::record("ke_end", ke_end);
  scenes::record("v_max_end_over_g_dt", v_max / (kG * kDt));
  scenes::record("ke_end_over_ke_free", ke_end / last.kinetic_energy_free);
  EXPECT_LE(ke_end, 1e-2 * last.kinetic_energy_free);
  EXPECT_LE(ke_end, 1e-6 * ke_peak);
}

}  // namespace
}  // namespace dilatant::settling_packing_test
