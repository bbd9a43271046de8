// The benchmark packing (bench/sweep_packing.hpp).
#include "sweep_packing.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "detection/contact_detector.hpp"
#include "solver/time_stepper.hpp"
#include "world/world.hpp"

namespace dilatant::bench {

using Clock = std::chrono::steady_clock;

namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// Volume of the part of a sphere (centre height z, radius r) between z = a and z = b.
double sphere_slab_volume(double z, double r, double a, double b) {
  const double lo = std::clamp(a - z, -r, r), hi = std::clamp(b - z, -r, r);
  auto below = [r](double h) { return std::numbers::pi * (r * r * h - h * h * h / 3.0); };
  return below(hi) - below(lo);
}

// Random sequential addition of non-overlapping spheres at kPhiLoose in a tall cell.
World loose_random_world(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(kRadiusMin, kRadiusMax), unit(0.0, 1.0);
  std::vector<double> radii(kSpheres);
  double volume = 0.0;
  for (double& r : radii) {
    r = radius(rng);
    volume += sphere_volume(r);
  }
  std::sort(radii.rbegin(), radii.rend());  // big ones first: fewer rejected trials
  const double height = volume / (kPhiLoose * kLx * kLy) + 2.0 * kRadiusMax;

  World world;
  world.box.length = Vec3(kLx, kLy, height);
  world.box.periodic = {true, true, false};
  world.planes.push_back(Plane{Vec3::Zero(), Vec3::UnitZ()});             // floor
  world.planes.push_back(Plane{Vec3(0.0, 0.0, height), -Vec3::UnitZ()});  // ceiling
  Bodies& b = world.bodies;
  for (int n = 0; n < kSpheres; ++n) {
    const double r = radii[static_cast<std::size_t>(n)];
    for (;;) {
      const Vec3 x(kLx * unit(rng), kLy * unit(rng), r + (height - 2.0 * r) * unit(rng));
      bool free = true;
      for (std::size_t j = 0; j < b.size() && free; ++j) {
        free = world.box.minimum_image(x, b.position[j]).norm() > r + b.radius[j];
      }
      if (free) {
        b.add_sphere(n, x, r, 1.0, false);
        break;
      }
    }
  }
  return world;
}

double largest_overlap(const World& world) {
  std::vector<Contact> touching;
  ContactDetector().detect(world, 0.0, touching);
  double overlap = 0.0;
  for (const Contact& c : touching) overlap = std::max(overlap, -c.gap);
  return overlap;
}

void bring_to_rest(Bodies& b) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.velocity[i].setZero();
    b.angular_velocity[i].setZero();
  }
}

// Lowers the ceiling to kLz (see the top of the file); returns the steps taken.
int compress(World& world, double& overlap) {
  TimeStepper compression(CoulombLaw{0.0}, SolverSettings{.tolerance = 1e-3, .max_iterations = 300},
                          kDt);
  TimeStepper relaxation(CoulombLaw{0.0}, SolverSettings{.tolerance = 1e-6, .max_iterations = 1000},
                         kDt);
  Bodies& b = world.bodies;
  Plane& ceiling = world.planes.at(1);
  const double h0 = ceiling.point.z();
  int steps = 0;
  for (int k = 1; k <= kIncrements; ++k, ++steps) {
    const double h = h0 * std::pow(kLz / h0, static_cast<double>(k) / kIncrements);
    const double rate = (h / ceiling.point.z() - 1.0) / kDt;
    for (std::size_t i = 0; i < b.size(); ++i) b.velocity[i].z() = rate * b.position[i].z();
    ceiling.point.z() = h;
    world.box.length.z() = h;
    compression.step(world);
    bring_to_rest(b);
  }
  // Overlaps left by the last increments are pushed apart at rest. (The stepper's
  // detection margin follows the bodies' speeds, 0 here, so a push may run into
  // an undetected neighbour; the next step catches it. Hence the loop.)
  overlap = largest_overlap(world);
  for (int k = 0; k < kMaxRelaxSteps && overlap > kMaxOverlap; ++k, ++steps) {
    relaxation.step(world);
    bring_to_rest(b);
    overlap = largest_overlap(world);
  }
  return steps;
}

// One step of `law` from `world` (copied), solved to 1e-6 or max_iterations.
Case shear_step(World world, FrictionLaw law, int max_iterations) {
  TimeStepper stepper(law, SolverSettings{.tolerance = 1e-6, .max_iterations = max_iterations},
                      kDt);
  const StepReport report = stepper.step(world);
  return Case{std::move(law), std::move(world.bodies), stepper.contacts(), report.solve};
}

Packing build_packing() {
  const auto start = Clock::now();
  Packing p;
  std::mt19937_64 rng(20240601);
  World world = loose_random_world(rng);
  p.compression_steps = compress(world, p.max_overlap);
  p.compression_seconds = std::chrono::duration<double>(Clock::now() - start).count();

  Bodies& b = world.bodies;
  p.bodies = static_cast<int>(b.size());
  double solid = 0.0, slab = 0.0;
  const double z_lo = 3.0, z_hi = kLz - 3.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    solid += sphere_volume(b.radius[i]);
    slab += sphere_slab_volume(b.position[i].z(), b.radius[i], z_lo, z_hi);
  }
  p.phi_cell = solid / (kLx * kLy * kLz);
  p.phi_bulk = slab / (kLx * kLy * (z_hi - z_lo));

  for (std::size_t i = 0; i < b.size(); ++i) {
    b.velocity[i] = Vec3(kShearRate * (b.position[i].z() - 0.5 * kLz), 0.0, 0.0);
    b.angular_velocity[i] = Vec3(0.0, 0.5 * kShearRate, 0.0);
  }
  p.coulomb = shear_step(world, CoulombLaw{kMu0}, 5000);

  // eta_f from the Coulomb step: s = eta_f * v_s * R_p / N with N = p_n / dt.
  std::vector<double> s_per_eta;
  for (const Contact& c : p.coulomb.contacts) {
    if (c.p_n > 0.0 && c.sliding_speed > 0.0) {
      s_per_eta.push_back(c.sliding_speed * c.reduced_radius * kDt / c.p_n);
    }
  }
  StribeckLaw stribeck;
  stribeck.mu0 = kMu0;
  if (!s_per_eta.empty()) {
    const auto median = s_per_eta.begin() + static_cast<std::ptrdiff_t>(s_per_eta.size() / 2);
    std::nth_element(s_per_eta.begin(), median, s_per_eta.end());
    stribeck.eta_f = stribeck.s_c / *median;
  }
  p.stribeck = shear_step(world, stribeck, 500);
  p.setup_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return p;
}

}  // namespace

const Packing& packing() {
  static const Packing p = build_packing();
  return p;
}

RegimeMix regime_mix(const std::vector<Contact>& contacts) {
  RegimeMix m;
  for (const Contact& c : contacts) {
    switch (c.regime) {
      case Regime::Open:
        m.open += 1;
        break;
      case Regime::Stick:
        m.stick += 1;
        break;
      case Regime::BoundaryLubricated:
        m.bl += 1;
        break;
      case Regime::Hydrodynamic:
        m.hd += 1;
        break;
      case Regime::Frictionless:  // the critical-load law's, which the benchmarks do not run
        m.frictionless += 1;
        break;
    }
  }
  const double n = static_cast<double>(contacts.size());
  return {m.open / n, m.stick / n, m.bl / n, m.hd / n, m.frictionless / n};
}

std::size_t loaded(const std::vector<Contact>& contacts) {
  return static_cast<std::size_t>(std::count_if(contacts.begin(), contacts.end(),
                                                [](const Contact& c) { return c.p_n > 0.0; }));
}

double contacts_per_sphere(const std::vector<Contact>& contacts, int bodies) {
  double n = 0.0;
  for (const Contact& c : contacts) {
    if (c.p_n > 0.0) n += c.with_plane() ? 1.0 : 2.0;
  }
  return n / bodies;
}

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

}  // namespace dilatant::bench
