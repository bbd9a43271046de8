#pragma once
// Scene mode (README "Scene configuration"): a world built from a particle CSV, planes, gravity and
// a possibly periodic box — for validation and teaching set-ups.
#include <vector>

#include "io/config.hpp"
#include "io/particles_csv.hpp"
#include "world/world.hpp"

namespace dilatant {

// Builds the world and checks that it is a legal initial state: non-negative
// ids (negative j in contacts.csv means a plane), fixed particles at rest, no
// overlap between particles or with planes beyond kOverlapTolerance * r_min, and
// periodic axes long enough for one nearest image. Throws InputError.
World build_scene_world(const Config& config, const std::vector<ParticleRecord>& particles);

// Relative overlap an input may have (round-off in hand-written coordinates).
inline constexpr double kOverlapTolerance = 1e-6;

// Automatic time step (solver.dt = 0): 1% of the time a particle needs to move
// its smallest radius, driven either by gravity (sqrt(r_min/|g|)) or by its
// initial speed (r_min/v_max), whichever is shorter; never longer than the
// trajectory interval. Throws InputError if neither sets a time scale.
double automatic_time_step(const World& world, const Config& config);

}  // namespace dilatant
