#include "drivers/sediment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "drivers/model_setup.hpp"
#include "drivers/packing_growth.hpp"

namespace dilatant {

namespace {

// The viscous relaxation time of a sphere of radius R = 1 and density 1 under
// Stokes drag, m / (6 pi eta_f R) = 2 R^2 rho_p / (9 eta_f), from St = g tau^2 / R
// with g = R = 1.
double relaxation_time(double stokes_number) { return std::sqrt(stokes_number); }

// Random spheres filling the box from floor to lid at phi_initial, grown from
// small radii to their own without overlaps (drivers/packing_growth.hpp).
World suspension(const SedimentSettings& s) {
  World world;
  world.box.length = Vec3(s.lx, s.ly, s.height);
  world.box.periodic = {true, true, false};
  world.planes.push_back(Plane{Vec3::Zero(), Vec3::UnitZ()});
  world.planes.push_back(Plane{Vec3(0.0, 0.0, s.height), -Vec3::UnitZ()});
  world.gravity = Vec3(0.0, 0.0, -1.0);

  std::mt19937_64 rng(static_cast<std::uint64_t>(s.seed));
  std::uniform_real_distribution<double> ur(s.radius_min, s.radius_max);
  std::uniform_real_distribution<double> ux(0.0, s.lx), uy(0.0, s.ly),
      uz(s.radius_max, s.height - s.radius_max);
  const double target = s.phi_initial * s.lx * s.ly * s.height;
  double volume = 0.0;
  for (;;) {
    const double r = ur(rng);
    const double v = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    if (volume + v > target) break;
    volume += v;
    // Sequenced draws (argument order is unspecified; g++ drew z, y, x).
    const double pz = uz(rng);
    const double py = uy(rng);
    const double px = ux(rng);
    world.bodies.add_sphere(static_cast<std::int64_t>(world.bodies.size()), Vec3(px, py, pz), r,
                            1.0, false);
  }
  const double initial_scale = std::min(1.0, std::cbrt(0.2 / s.phi_initial));
  const GrowthReport growth = grow_to_full_size(world, 0, initial_scale);
  if (growth.max_overlap > kPackingOverlapTolerance * s.radius_min) {
    throw std::runtime_error(
        fmt::format("could not pack the suspension at phi {} without overlaps (largest "
                    "overlap {:.3g}); lower the initial fraction",
                    s.phi_initial, growth.max_overlap));
  }
  return world;
}

}  // namespace

Sediment::Sediment(const SedimentSettings& settings)
    : settings_(settings),
      world_(suspension(settings)),
      terminal_speed_(relaxation_time(settings.stokes_number)),  // v_t = g tau, g = 1
      fluid_(make_fluid({.drag = DragKind::Stokes},
                        2.0 / (9.0 * relaxation_time(settings.stokes_number)))),
      // A step moves a sphere at most 2% of the smallest radius at the
      // terminal speed; the drag is implicit, so it sets no other limit.
      stepper_(CoulombLaw{.mu0 = settings.mu0, .eta_f = 0.0}, settings.solver,
               settings.dt > 0.0 ? settings.dt : 0.02 * settings.radius_min / terminal_speed_) {
  stepper_.set_fluid_forces(fluid_.get());
  stepper_.set_reference_force(weight_force(world_));
  dt_ = stepper_.dt();
  stepper_.set_shortest_dt(dt_ / kShortestStepDivisor);
  max_time_ = settings.max_time_factor * settings.height / terminal_speed_;
  window_start_height_ = mean_height();
}

double Sediment::mean_height() const {
  const Bodies& b = world_.bodies;
  double sum = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) sum += b.position[i][2];
  return b.size() > 0 ? sum / double(b.size()) : 0.0;
}

const StepReport& Sediment::step() {
  // Each step starts at the full dt, however short a redo made the last
  // (solver/time_stepper.hpp): settling keeps no time grid.
  stepper_.set_dt(dt_);
  last_ = stepper_.step(world_);
  ++steps_;
  max_overlap_ = std::max(max_overlap_, last_.max_overlap);
  const double window = kSettleWindow * settings_.radius_max / terminal_speed_;
  if (world_.time - window_start_time_ >= window) {
    const double h = mean_height();
    settled_ = std::abs(h - window_start_height_) < kSettleHeight * settings_.radius_max;
    window_start_time_ = world_.time;
    window_start_height_ = h;
  }
  return last_;
}

}  // namespace dilatant
