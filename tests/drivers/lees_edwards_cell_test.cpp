// The wall-free shear cell (cell.boundary = "lees-edwards";
// boundary/image_drive.hpp): its construction, its two controls, momentum
// across the sheared boundary, and fluid forces through it. The steady flow's
// physics is in lees_edwards_flow_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "detection/contact_detector.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "friction/coulomb_law.hpp"
#include "io/config.hpp"
#include "solver/slab_partition.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::lees_edwards_cell_test {
namespace {

Config le_cell(const std::vector<std::string>& extra = {}) {
  std::vector<std::string> overrides = {"cell.boundary=\"lees-edwards\"",
                                        "cell.size=[6.0, 5.0, 7.0]",
                                        "fluid.lambda=1.0",
                                        "run.strain=1.0",
                                        "run.transient_strain=0.5",
                                        "run.snapshot_interval=0",
                                        "solver.max_iterations=200"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return default_cell_config(overrides);
}

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

TEST(LeesEdwardsCell, IsATriplyPeriodicBoxOfMobileSpheresAtTheExactFraction) {
  const Config config = le_cell();
  ShearCellGeometry g;
  ImageControl control;
  const World w = build_lees_edwards_cell(config, g, control);
  const CellConfig& cell = *config.cell();
  EXPECT_TRUE(w.box.lees_edwards);
  EXPECT_EQ(w.box.periodic, (std::array<bool, 3>{true, true, true}));
  EXPECT_TRUE(w.planes.empty());
  double volume = 0.0;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    EXPECT_FALSE(w.bodies.is_fixed(i));  // no wall spheres
    volume += sphere_volume(w.bodies.radius[i]);
  }
  const double box = cell.size[0] * cell.size[1] * cell.size[2];
  EXPECT_EQ(g.mobile_count, w.bodies.size());
  EXPECT_DOUBLE_EQ(g.phi_box, volume / box);
  EXPECT_EQ(g.phi, g.phi_box);
  // Radii are drawn until the next would overshoot phi: short by less than
  // one sphere.
  EXPECT_LE(g.phi_box, cell.phi);
  EXPECT_GT(g.phi_box, cell.phi - sphere_volume(cell.radius_max) / box);
  // Started on the centred linear profile, the images at V = rate Lz.
  const double rate = cell.initial_shear_rate;
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, rate * cell.size[2]);
  for (std::size_t i = 0; i < w.bodies.size(); ++i)
    EXPECT_DOUBLE_EQ(w.bodies.velocity[i][0],
                     rate * (w.bodies.position[i][2] - 0.5 * cell.size[2]));
  // The default fictitious mass is the wall cell's top wall for this seed.
  ShearCellGeometry wg;
  RoughWalls walls;
  build_shear_cell(default_cell_config({"cell.size=[6.0, 5.0, 7.0]"}), wg, walls);
  EXPECT_EQ(control.mass, walls.top().mass);
  EXPECT_DOUBLE_EQ(control.drive_force, cell.shear_stress * cell.size[0] * cell.size[1]);
}

// Rate control: the images move at gamma_dot Lz at every step, so the strain
// is gamma_dot t to round-off, and the summary reports that rate with no error.
TEST(LeesEdwardsCell, RateControlImposesTheStrainRateExactly) {
  const double rate = 0.3;
  ShearCell cell(le_cell({"cell.control=\"rate\"", "cell.shear_rate=0.3"}));
  const double lz = cell.config().cell()->size[2];
  for (int k = 0; k < 300; ++k) {
    cell.step();
    ASSERT_EQ(cell.state().world.box.shear_velocity, rate * lz);
  }
  EXPECT_NEAR(cell.state().strain, rate * cell.state().world.time, 1e-12 * cell.state().strain);
  EXPECT_GT(cell.state().strain, 0.01);
}

// Momentum across the sheared boundary (geometry/periodic_box.hpp): every
// contact impulse acts on two bodies with opposite signs, the cell has no
// gravity, drag or walls, so the total momentum is constant except when a body
// crosses z: stored back in the box, its x velocity drops by V per copy up
// (wrap_body). Under rate control V is constant, so over any stretch of steps
//     P_x(end) - P_x(start) = -V sum_n m_n k_n ,   P_y, P_z constant,
// k_n the net number of crossings up of body n.
TEST(LeesEdwardsCell, MomentumChangesOnlyByTheCrossingsImageVelocity) {
  ShearCell cell(le_cell({"cell.control=\"rate\"", "cell.shear_rate=0.5"}));
  const double lz = cell.config().cell()->size[2];
  const auto momentum = [&] {
    const Bodies& b = cell.state().world.bodies;
    Vec3 p = Vec3::Zero();
    double scale = 0.0;
    for (std::size_t n = 0; n < b.size(); ++n) {
      p += b.mass(n) * b.velocity[n];
      scale += b.mass(n) * b.velocity[n].norm();
    }
    return std::pair{p, scale};
  };
  for (int k = 0; k < 50; ++k) cell.step();  // contacts formed
  const auto [start, scale] = momentum();
  const double speed = cell.state().world.box.shear_velocity;
  double shift = 0.0;  // sum_n m_n k_n
  int crossings = 0;
  for (int k = 0; k < 1500; ++k) {
    const std::vector<Vec3> before = cell.state().world.bodies.position;
    cell.step();
    const Bodies& b = cell.state().world.bodies;
    for (std::size_t n = 0; n < b.size(); ++n) {
      const double dz = b.position[n][2] - before[n][2];
      if (std::abs(dz) > 0.5 * lz) {
        shift += dz < 0.0 ? b.mass(n) : -b.mass(n);  // wrapped down: crossed the top
        ++crossings;
      }
    }
  }
  const Vec3 end = momentum().first;
  // Round-off of ~1e5 velocity updates of size `scale`.
  EXPECT_NEAR(end[0] - start[0], -speed * shift, 1e-10 * scale);
  EXPECT_NEAR(end[1], start[1], 1e-10 * scale);
  EXPECT_NEAR(end[2], start[2], 1e-10 * scale);
  // Not vacuous: bodies did cross, and the shift is of the momentum's size.
  EXPECT_GT(crossings, 0);
  EXPECT_GT(speed * std::abs(shift), 1e-6 * scale);
}

// A pair once inside the box and once through its top: sphere 1 moved up by
// `up` lies beyond z = Lz and is stored at the bottom, x shifted back by the
// offset and v_x by the images' speed (wrap_body).
struct PairAcross {
  World inside, across;
  double speed = 1.3;
};

PairAcross pair_across(const Vec3& x0, const Vec3& v0, const Vec3& x1, const Vec3& v1) {
  PairAcross p;
  for (World* w : {&p.inside, &p.across}) {
    w->box.length = Vec3(8.0, 6.0, 9.0);
    w->box.periodic = {true, true, true};
    w->box.lees_edwards = true;
    w->box.shear_offset = 2.1;
    w->box.shear_velocity = p.speed;
  }
  p.inside.bodies.add_sphere(0, x0, 1.0, 1.0, false, v0);
  p.inside.bodies.add_sphere(1, x1, 1.0, 1.0, false, v1);
  const Vec3 up(0.0, 0.0, 4.6);
  p.across.bodies.add_sphere(0, x0 + up, 1.0, 1.0, false, v0);
  Vec3 y1 = x1 + up, w1 = v1;
  p.across.box.wrap_body(y1, w1);
  EXPECT_LT(y1[2], 2.0);  // stored at the bottom, across the boundary
  p.across.bodies.add_sphere(1, y1, 1.0, 1.0, false, w1);
  return p;
}

// After one step of each: the same impulse, and the same velocities seen
// from the same copy (sphere 1 plus the images' speed). Returns the contact
// inside the box.
Contact expect_same_step(PairAcross& p, const FrictionLaw& law, SuspendingFluid* fluid) {
  const SolverSettings settings{.tolerance = 1e-12, .max_iterations = 10000};
  TimeStepper a(law, settings, 1e-3), b(law, settings, 1e-3);
  a.set_fluid_forces(fluid);
  b.set_fluid_forces(fluid);
  a.step(p.inside);
  b.step(p.across);
  EXPECT_EQ(a.contacts().size(), 1u);
  EXPECT_EQ(b.contacts().size(), 1u);
  if (a.contacts().size() != 1u || b.contacts().size() != 1u) return Contact{};
  const Contact &ca = a.contacts()[0], &cb = b.contacts()[0];
  const double scale = ca.p_n + ca.p_lub + ca.p_t.norm();
  EXPECT_NEAR(cb.p_n, ca.p_n, 1e-10 * scale);
  EXPECT_NEAR(cb.p_lub, ca.p_lub, 1e-10 * scale);
  EXPECT_NEAR((cb.p_t - ca.p_t).norm(), 0.0, 1e-10 * scale);
  const Bodies &in = p.inside.bodies, &ac = p.across.bodies;
  EXPECT_NEAR((ac.velocity[0] - in.velocity[0]).norm(), 0.0, 1e-10);
  EXPECT_NEAR((ac.velocity[1] + Vec3(p.speed, 0.0, 0.0) - in.velocity[1]).norm(), 0.0, 1e-10);
  EXPECT_NEAR((ac.angular_velocity[1] - in.angular_velocity[1]).norm(), 0.0, 1e-10);
  return ca;
}

// The squeeze film across the boundary (fluid/squeeze_film.hpp): a gap of
// 0.05 R closing at ~1 R per unit time, the film acts and no contact closes.
TEST(LeesEdwardsCell, ASqueezeFilmThroughTheBoundaryActsAsInsideTheBox) {
  const Vec3 x0(4.0, 3.0, 4.0);
  PairAcross p = pair_across(x0, Vec3(0.3, 0.0, 0.5), x0 + 2.05 * Vec3(0.1, 0.05, 1.0).normalized(),
                             Vec3(-0.2, 0.1, -0.5));
  FluidConfig fluid;
  fluid.lubrication = LubricationKind::Normal;
  const auto film = make_fluid(fluid, 0.5);
  const Contact c = expect_same_step(p, CoulombLaw{.mu0 = 0.4, .eta_f = 0.5}, film.get());
  EXPECT_GT(c.p_lub, 0.0);  // the film resists the approach
  EXPECT_EQ(c.p_n, 0.0);    // and no contact closes
}

// A contact through the boundary under the cell's own law, the Stribeck
// friction of the paper (friction/stribeck_law.hpp), whose Sommerfeld number
// reads the sliding speed: with the images' offset in the relative velocity,
// the impulse is the one inside the box (a sliding speed seen without the
// offset would differ by V = 1.3 and change the friction).
TEST(LeesEdwardsCell, AStribeckContactThroughTheBoundaryActsAsInsideTheBox) {
  const Vec3 x0(4.0, 3.0, 4.0);
  PairAcross p =
      pair_across(x0, Vec3(0.3, 0.0, 0.9), x0 + Vec3(0.3, 0.2, 1.95), Vec3(-0.2, 0.1, -0.8));
  const FrictionLaw law = make_friction_law(FrictionConfig{}, 0.1, 0.0);
  const Contact c = expect_same_step(p, law, nullptr);
  EXPECT_GT(c.p_n, 0.0);
  EXPECT_GT(c.p_t.norm(), 0.0);  // friction acts
}

// The Stokes drag relative to the box's shear U = rate (z - Lz/2) x
// (fluid/stokes_drag.hpp), rate = V / Lz as the cell sets it. Both contacts
// and that drag are invariant under moving every body up by h with velocity
// + rate h x: a pair in contact moved up so that sphere 1 leaves through the
// top (stored at the bottom with v_x - V: U there is lower by rate Lz = V too)
// must take the same impulse and keep the same velocities relative to U. A
// drag taken against the stored copy's own height without the images' speed
// would differ by 6 pi eta_f r V.
TEST(LeesEdwardsCell, TheDragThroughTheBoundaryActsAsInsideTheBox) {
  const double speed = 1.3, lz = 9.0, rate = speed / lz, h = 4.6;
  const auto box = [&] {
    World w;
    w.box.length = Vec3(8.0, 6.0, lz);
    w.box.periodic = {true, true, true};
    w.box.lees_edwards = true;
    w.box.shear_offset = 2.1;
    w.box.shear_velocity = speed;
    return w;
  };
  const Vec3 x0(4.0, 3.0, 4.0), x1 = x0 + Vec3(0.3, 0.2, 1.95);
  const Vec3 v0(0.3, 0.0, 0.9), v1(-0.2, 0.1, -0.8), up(0.0, 0.0, h), flow_up(rate * h, 0, 0);
  const auto pair_inside = [&] {
    World w = box();
    w.bodies.add_sphere(0, x0, 1.0, 1.0, false, v0);
    w.bodies.add_sphere(1, x1, 1.0, 1.0, false, v1);
    return w;
  };
  World inside = pair_inside(), across = box(), dry = pair_inside();
  across.bodies.add_sphere(0, x0 + up, 1.0, 1.0, false, v0 + flow_up);
  Vec3 y1 = x1 + up, w1 = v1 + flow_up;
  across.box.wrap_body(y1, w1);
  ASSERT_LT(y1[2], 2.0);  // stored at the bottom, across the boundary
  across.bodies.add_sphere(1, y1, 1.0, 1.0, false, w1);

  FluidConfig fluid;
  fluid.drag = DragKind::Stokes;
  fluid.lubrication = LubricationKind::None;
  const double eta_f = 0.5;
  const auto drag = make_fluid(fluid, eta_f);
  ASSERT_TRUE(drag);
  drag->set_ambient({.shear_rate = rate, .z0 = 0.5 * lz});
  const CoulombLaw law{.mu0 = 0.4, .eta_f = eta_f};
  const SolverSettings settings{.tolerance = 1e-12, .max_iterations = 10000};
  TimeStepper a(law, settings, 1e-2), b(law, settings, 1e-2);
  a.set_fluid_forces(drag.get());
  b.set_fluid_forces(drag.get());
  a.step(inside);
  b.step(across);
  ASSERT_EQ(a.contacts().size(), 1u);
  ASSERT_EQ(b.contacts().size(), 1u);
  const Contact &ca = a.contacts()[0], &cb = b.contacts()[0];
  const double scale = ca.p_n + ca.p_t.norm();
  EXPECT_GT(ca.p_n, 0.0);
  EXPECT_NEAR(cb.p_n, ca.p_n, 1e-10 * scale);
  EXPECT_NEAR((cb.p_t - ca.p_t).norm(), 0.0, 1e-10 * scale);
  const Bodies &in = inside.bodies, &ac = across.bodies;
  EXPECT_NEAR((ac.velocity[0] - flow_up - in.velocity[0]).norm(), 0.0, 1e-10);
  EXPECT_NEAR((ac.velocity[1] - flow_up + Vec3(speed, 0, 0) - in.velocity[1]).norm(), 0.0, 1e-10);
  EXPECT_NEAR((ac.angular_velocity[0] - in.angular_velocity[0]).norm(), 0.0, 1e-10);
  EXPECT_NEAR((ac.angular_velocity[1] - in.angular_velocity[1]).norm(), 0.0, 1e-10);
  // Not vacuous: over this step the drag changed the velocities by much more
  // than the tolerance (its relaxation time m / (6 pi eta_f r) ~ 0.44).
  TimeStepper c(law, settings, 1e-2);
  c.step(dry);
  EXPECT_GT((dry.bodies.velocity[0] - in.velocity[0]).norm(), 1e-3);
}

// The parallel sweep wraps its red-black slabs around the periodic z
// (solver/slab_partition.hpp): the box of 11 R holds 4 slabs, so two threads
// really share sweeps, and give the same bits as one.
TEST(LeesEdwardsCell, TwoThreadsGiveTheSameBitsAsOne) {
  const std::string size = "cell.size=[6.0, 5.0, 11.0]";
  {
    ShearCellGeometry g;
    ImageControl control;
    const World world = build_lees_edwards_cell(le_cell({size}), g, control);
    std::vector<Contact> contacts, scratch;
    ContactDetector().detect(world, 0.1, contacts);
    ASSERT_GE(partition_into_slabs(contacts, world, scratch).count(), 4);
  }
  ShearCell one(le_cell({size, "solver.threads=1"})), two(le_cell({size, "solver.threads=2"}));
  // Few steps: two threads on a loaded machine wait at every sweep's barriers.
  for (int k = 0; k < 40; ++k) {
    one.step();
    two.step();
  }
  const Bodies &a = one.state().world.bodies, &b = two.state().world.bodies;
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.angular_velocity, b.angular_velocity);
  EXPECT_EQ(one.state().world.box.shear_velocity, two.state().world.box.shear_velocity);
  EXPECT_EQ(one.state().strain, two.state().strain);
}

// Continuation checks the boundary as well as the size: a wall cell's state
// cannot go on without walls.
TEST(LeesEdwardsCell, ContinuationRefusesAStateOfTheOtherBoundary) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("dilatant_le_continue_" + std::to_string(::getpid()) + ".bin");
  ShearCell walls(default_cell_config({"cell.size=[6.0, 5.0, 7.0]"}));
  walls.step();
  walls.write_checkpoint(file);
  try {
    ShearCell::continued(le_cell(), file);
    ADD_FAILURE() << "a wall cell's state continued as a Lees-Edwards cell";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cell.boundary = \"lees-edwards\""), std::string::npos)
        << e.what();
  }
  ShearCell le(le_cell());
  le.step();
  le.write_checkpoint(file);
  EXPECT_THROW(ShearCell::continued(default_cell_config({"cell.size=[6.0, 5.0, 7.0]"}), file),
               std::runtime_error);
  // The same boundary continues, with this config's control.
  const ShearCell next =
      ShearCell::continued(le_cell({"cell.control=\"rate\"", "cell.shear_rate=0.4"}), file);
  EXPECT_EQ(next.state().world.box.shear_velocity, 0.4 * 7.0);
  EXPECT_EQ(next.state().strain, 0.0);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace dilatant::lees_edwards_cell_test
