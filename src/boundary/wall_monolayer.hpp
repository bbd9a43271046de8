#pragma once
// A rough wall of the shear cell: a random, non-overlapping monolayer of glued
// spheres with centres on one plane z = z0 (docs/model.md "The shear cell").
//
// Centres are placed by random sequential adsorption of their discs in the
// periodic Lx x Ly rectangle, continued until `kSaturationAttempts` attempts in
// a row fail, which is close to the RSA jamming coverage (~0.55 for discs): the
// holes left are smaller than a particle, so the wall is as dense as a random
// monolayer gets without ordering.
#include <random>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

struct WallSphere {
  Vec3 position;
  double radius;
};

inline constexpr int kSaturationAttempts = 20000;

std::vector<WallSphere> random_monolayer(double lx, double ly, double z0, double radius_min,
                                         double radius_max, std::mt19937_64& rng);

}  // namespace dilatant
