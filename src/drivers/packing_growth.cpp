#include "drivers/packing_growth.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "boundary/fixed_walls.hpp"
#include "detection/contact_detector.hpp"
#include "drivers/setup_monitor.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

namespace {

// Inflation per step: 0.3% of the radius keeps the new overlaps small enough
// that one linearised projection removes them.
constexpr double kInflationFactor = 1.003;
constexpr int kMaxFinalRelaxations = 2000;

// Largest overlap of the current positions, from a fresh detection: the
// projection's own contact list cannot see pairs its displacements created.
double largest_overlap(const World& world) {
  static thread_local ContactDetector detector;
  static thread_local std::vector<Contact> contacts;
  detector.detect(world, 0.0, contacts);
  double overlap = 0.0;
  for (const Contact& c : contacts) overlap = std::max(overlap, -c.gap);
  return overlap;
}

double project_out_overlaps(World& world, TimeStepper& projector, Boundary& walls) {
  Bodies& b = world.bodies;
  std::fill(b.velocity.begin(), b.velocity.end(), Vec3::Zero());
  std::fill(b.angular_velocity.begin(), b.angular_velocity.end(), Vec3::Zero());
  projector.step(world, &walls);
  std::fill(b.velocity.begin(), b.velocity.end(), Vec3::Zero());
  std::fill(b.angular_velocity.begin(), b.angular_velocity.end(), Vec3::Zero());
  return largest_overlap(world);
}

}  // namespace

GrowthReport grow_to_full_size(World& world, std::size_t first, double initial_scale) {
  Bodies& b = world.bodies;
  const std::vector<double> final_radius(b.radius.begin(), b.radius.end());
  const double r_min =
      *std::min_element(final_radius.begin() + static_cast<long>(first), final_radius.end());
  const Vec3 gravity = world.gravity;
  world.gravity = Vec3::Zero();
  const double time = world.time;
  const CoulombLaw frictionless{.mu0 = 0.0, .eta_f = 0.0};
  // Plain Gauss–Seidel (no over-relaxation): a projection, not a flow.
  TimeStepper projector(frictionless,
                        SolverSettings{.tolerance = 1e-4, .max_iterations = 500, .relaxation = 1.0},
                        1.0);
  FixedWalls walls(frictionless);

  GrowthReport report;
  // Progress in log(scale): each inflation multiplies it by kInflationFactor.
  const double growth = std::log(1.0 / initial_scale);
  for (double scale = initial_scale; scale < 1.0;) {
    setup_pass("growing the packing",
               growth > 0.0 ? std::log(scale / initial_scale) / growth : 1.0);
    scale = std::min(1.0, scale * kInflationFactor);
    for (std::size_t i = first; i < b.size(); ++i) b.radius[i] = scale * final_radius[i];
    report.max_overlap = project_out_overlaps(world, projector, walls);
    ++report.inflation_steps;
  }
  while (report.max_overlap > kPackingOverlapTolerance * r_min &&
         report.relaxation_steps < kMaxFinalRelaxations) {
    setup_pass("relaxing the packing",
               static_cast<double>(report.relaxation_steps) / kMaxFinalRelaxations);
    report.max_overlap = project_out_overlaps(world, projector, walls);
    ++report.relaxation_steps;
  }
  world.gravity = gravity;
  world.time = time;
  return report;
}

}  // namespace dilatant
