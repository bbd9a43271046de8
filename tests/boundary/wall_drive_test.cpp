// The wall cell's drive (boundary/wall_drive.hpp) against the mechanics of a
// rigid wall pulled by a constant force: the shear rate it imposes, the power
// it feeds in (tau gamma_dot times the volume), its kinetic energy, its bound
// on the time step, its mean flow and normal stress, and continuation.
#include "boundary/wall_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "boundary/drive_record.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant::wall_drive_test {
namespace {

constexpr double kLx = 4.0, kLy = 5.0, kLz = 6.0;

// A cell of Lx Ly Lz whose top wall is one glued sphere (body 0) of mass M
// (as a rigid body) at speed V under the stress tau.
struct OneSphereCell {
  World world;
  WallDrive drive;
};

OneSphereCell one_sphere_cell(double tau, double mass, double velocity) {
  World world;
  world.box.length = Vec3(kLx, kLy, kLz);
  world.box.periodic = {true, true, false};
  world.bodies.add_sphere(0, Vec3(0.0, 0.0, kLz), 1.0, 1.0, /*fixed=*/true);
  world.bodies.set_driven(0, kTopWall);
  const DriveSpec spec{.shear_stress = tau, .size = world.box.length};
  SlidingWall top{.spheres = {0},
                  .mass = mass,
                  .drive_force = WallDrive::drive_force(spec),
                  .velocity = velocity};
  RoughWalls walls(std::move(top), CoulombLaw{});
  return {std::move(world),
          WallDrive(std::move(walls), {.wall_radius_mean = 0.5, .gap_height = kLz - 1.0})};
}

// gamma_dot = V / Lz, and the power F V = tau Lx Ly gamma_dot Lz = tau
// gamma_dot times the volume. A wall too heavy to accelerate within the step
// feeds exactly that (to round-off).
TEST(WallDrive, FeedsTheStressTimesTheRateTimesTheVolume) {
  const double tau = 0.5, rate = 0.2, dt = 0.01;
  OneSphereCell c = one_sphere_cell(tau, 1e12, rate * kLz);
  EXPECT_DOUBLE_EQ(c.drive.speed(c.world), rate * kLz);
  EXPECT_DOUBLE_EQ(c.drive.shear_rate(c.world), rate);
  TimeStepper stepper(CoulombLaw{}, SolverSettings{}, dt);
  stepper.step(c.world, c.drive.contact_block());
  EXPECT_NEAR(c.drive.fed_work(c.world, 0.0, dt) / dt, tau * rate * kLx * kLy * kLz, 1e-12);
}

// Alone, the wall turns all the drive's work into its own kinetic energy,
// F dt (V + dt F / 2M) = M (V_1^2 - V_0^2) / 2, which the cell counts beside
// the bodies' (theirs: the wall's spheres have infinite mass).
TEST(WallDrive, AloneItsWorkIsItsKineticEnergyGain) {
  const double dt = 0.05;
  OneSphereCell c = one_sphere_cell(0.1, 3.0, 0.4);
  const double before = c.drive.kinetic_energy();
  TimeStepper stepper(CoulombLaw{}, SolverSettings{}, dt);
  for (int n = 0; n < 10; ++n) {
    const double start = c.drive.kinetic_energy();
    stepper.step(c.world, c.drive.contact_block());
    c.drive.respond(c.world, {}, dt);  // nothing: the wall answered within the step
    EXPECT_NEAR(c.drive.fed_work(c.world, 0.0, dt), c.drive.kinetic_energy() - start, 1e-13);
  }
  const double force = 0.1 * kLx * kLy, v = 0.4 + 10 * dt * force / 3.0;
  EXPECT_NEAR(c.drive.kinetic_energy() - before, 0.5 * 3.0 * (v * v - 0.4 * 0.4), 1e-12);
}

// From rest the drive alone moves the wall by F t^2 / 2M: by `reach` at the bound.
TEST(WallDrive, BoundsTheStepByTheDisplacementItsForceCauses) {
  OneSphereCell c = one_sphere_cell(0.3, 2.0, 0.0);
  const double reach = 0.02, dt = c.drive.time_step_bound(c.world, reach, kLz);
  const double acceleration = 0.3 * kLx * kLy / 2.0;
  EXPECT_NEAR(0.5 * acceleration * dt * dt, reach, 1e-15);
}

// The no-slip profile between the walls' mean surfaces; the normal stress is
// the particles' mean push on the two walls; the bulk is the gap's central half.
TEST(WallDrive, MeasuresOnItsWallsAndTheCentralHalfOfTheGap) {
  OneSphereCell c = one_sphere_cell(0.3, 2.0, 1.5);
  const ShearFlow flow = c.drive.mean_flow(c.world);
  EXPECT_DOUBLE_EQ(flow.shear_rate, 1.5 / (kLz - 1.0));
  EXPECT_EQ(flow.z0, 0.5);
  const WallForces f{.bottom = Vec3(0.0, 0.0, -2.0), .top = Vec3(1.0, 0.0, 4.0)};
  EXPECT_DOUBLE_EQ(c.drive.normal_stress(c.world, f, 99.0), 3.0 / (kLx * kLy));
  const BulkRegion bulk = c.drive.bulk_region(c.world);
  EXPECT_EQ(bulk.z_lo, 0.25 * kLz);
  EXPECT_EQ(bulk.z_hi, 0.75 * kLz);
  EXPECT_FALSE(bulk.whole_box);
  EXPECT_TRUE(c.drive.bounded_by_walls());
}

// Continuation takes the next point's stress; it refuses images or another
// height (the walls stand where the state put them).
TEST(WallDrive, ContinuesUnderAnotherStressButNotAsAnotherCell) {
  OneSphereCell c = one_sphere_cell(0.3, 2.0, 1.5);
  EXPECT_FALSE(c.drive.adopt({.kind = DriveKind::Images, .size = c.world.box.length}, c.world));
  EXPECT_FALSE(c.drive.adopt({.shear_stress = 0.7, .size = Vec3(kLx, kLy, 9.0)}, c.world));
  EXPECT_DOUBLE_EQ(c.drive.record(c.world).wall.drive_force, 0.3 * kLx * kLy);
  ASSERT_TRUE(c.drive.adopt({.shear_stress = 0.7, .size = c.world.box.length}, c.world));
  const DriveRecord r = c.drive.record(c.world);
  EXPECT_DOUBLE_EQ(r.wall.drive_force, 0.7 * kLx * kLy);
  EXPECT_EQ(r.wall.mass, 2.0);  // the spec names no mass: kept
  EXPECT_EQ(r.wall.velocity, 1.5);
}

// The record keeps each body's owner, one byte a body as format 7 keeps its
// "body groups" (0 particle, 1 bottom wall, 2 top wall); restoring the drive
// gives the bodies of a checkpoint, read without them, their motion back.
TEST(WallDrive, ItsRecordKeepsWhichWallOwnsEachBody) {
  OneSphereCell c = one_sphere_cell(0.3, 2.0, 1.5);
  c.world.bodies.add_sphere(1, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, /*fixed=*/true);
  c.world.bodies.set_driven(1, kBottomWall);
  c.world.bodies.add_sphere(2, Vec3(0.0, 0.0, 3.0), 1.0, 1.0, false);
  const DriveRecord r = c.drive.record(c.world);
  EXPECT_EQ(r.owners, (std::vector<OwnerId>{2, 1, 0}));
  EXPECT_EQ(r.fault(c.world.box, 3), nullptr);
  EXPECT_STREQ(r.fault(c.world.box, 4), "body groups");
  World read = c.world;
  read.bodies.motion.clear();
  read.bodies.owner.clear();
  const auto back = restore_drive(r, read, {});
  ASSERT_NE(dynamic_cast<const WallDrive*>(back.get()), nullptr);
  EXPECT_EQ(read.bodies.owner, c.world.bodies.owner);
  EXPECT_EQ(read.bodies.motion,
            (std::vector<Motion>{Motion::Driven, Motion::Driven, Motion::Dynamic}));
}

}  // namespace
}  // namespace dilatant::wall_drive_test
