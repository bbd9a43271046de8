// The squeeze films' resistance to the pressure-controlled box's lid
// (boundary/lid_resistance.hpp): c = -dp/dW, the bodies held fixed, checked
// against the films' own law as the solver applies it (the relative velocity
// with the dilation's drift, solver/local_problem.hpp; the film's impulse
// -k u_n, solve_normal_with_film with the bodies immovable, w_n = 0) and the
// virial p = (1/V) sum d_z F_z (measure/particle_stress.hpp).
#include "boundary/lid_resistance.hpp"

#include <gtest/gtest.h>

#include "solver/local_problem.hpp"
#include "world/world.hpp"

namespace dilatant::boundary::lid_resistance_test {
namespace {

constexpr double kLz = 8.0, kVolume = 4.0 * 5.0 * kLz, kDt = 0.01;

// A pair i = 1 above partner 0 along a tilted normal, with a film of
// coefficient k, both at rest: what the dilation rate W / H makes of it.
Contact tilted_pair(double k) {
  Contact c;
  c.i = 1;
  c.other = 0;
  c.normal = Vec3(0.6, 0.0, 0.8);
  c.gap = 0.01;
  c.arm_i = 0.5;
  c.arm_j = 0.5;
  c.lubrication = k;
  return c;
}

// p = -sigma_zz of the pair's film at lid speed w, the bodies fixed.
double film_pressure(Contact c, const Bodies& bodies, double w) {
  const Vec3 d = (c.arm_i + c.arm_j + c.gap) * c.normal;
  c.dilation_drift = (w / kLz) * d[2];
  const double u_n = relative_velocity(c, bodies).dot(c.normal);
  const NormalAnswer film = solve_normal_with_film(u_n, c.gap / kDt, 0.0, c.lubrication);
  EXPECT_EQ(film.p_n, 0.0);  // the gap stays open: the film alone answers
  const double force_z = (film.p_lub + film.p_n) * c.normal[2] / kDt;
  return d[2] * force_z / kVolume;
}

TEST(LidResistance, IsMinusTheFilmsPressureResponseToTheLidsSpeed) {
  World world;
  world.bodies.add_sphere(0, Vec3(1.0, 1.0, 1.0), 0.5, 1.0, false);
  world.bodies.add_sphere(1, Vec3(1.606, 1.0, 1.808), 0.5, 1.0, false);
  const double k = 40.0;
  const Contact c = tilted_pair(k);
  const double c_lid = film_lid_resistance({c}, kVolume, kLz, kDt);
  // (k / dt) (d_z n_z)^2 / (V H), d_z n_z = 1.01 * 0.8 * 0.8.
  const double dz_nz = 1.01 * 0.64;
  EXPECT_NEAR(c_lid, (k / kDt) * dz_nz * dz_nz / (kVolume * kLz), 1e-12 * c_lid);
  // p is linear in W: its slope is -c exactly, a compressing lid (W < 0)
  // raising it.
  const double w = 1e-3;
  const double slope =
      (film_pressure(c, world.bodies, w) - film_pressure(c, world.bodies, -w)) / (2.0 * w);
  EXPECT_NEAR(slope, -c_lid, 1e-9 * c_lid);
  EXPECT_GT(film_pressure(c, world.bodies, -w), 0.0);
}

// Pairs side by side (n along x) and contacts without a film resist the lid
// not at all; contacts add up.
TEST(LidResistance, OnlyFilmsAcrossTheShearPlanesCount) {
  Contact side = tilted_pair(40.0);
  side.normal = Vec3(1.0, 0.0, 0.0);
  Contact dry = tilted_pair(0.0);
  const Contact tilted = tilted_pair(40.0);
  EXPECT_EQ(film_lid_resistance({side, dry}, kVolume, kLz, kDt), 0.0);
  EXPECT_DOUBLE_EQ(film_lid_resistance({tilted, side, tilted}, kVolume, kLz, kDt),
                   2.0 * film_lid_resistance({tilted}, kVolume, kLz, kDt));
}

}  // namespace
}  // namespace dilatant::boundary::lid_resistance_test
