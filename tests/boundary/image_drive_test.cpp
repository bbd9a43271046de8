// The Lees–Edwards images as a drive (boundary/image_drive.hpp): the rate they
// impose and the power they feed in (tau gamma_dot times the volume), their
// response to the measured stress under either control, their bound on the
// time step, their mean flow and bulk, and continuation.
#include "boundary/image_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "boundary/drive_record.hpp"

namespace dilatant::image_drive_test {
namespace {

constexpr double kLx = 4.0, kLy = 5.0, kLz = 6.0;

World box_at(double speed) {
  World w;
  w.box.length = Vec3(kLx, kLy, kLz);
  w.box.periodic = {true, true, true};
  w.box.lees_edwards = true;
  w.box.shear_velocity = speed;
  return w;
}

DriveSpec stress_spec(double tau) {
  return {.kind = DriveKind::Images, .shear_stress = tau, .size = Vec3(kLx, kLy, kLz)};
}

DriveSpec rate_spec(double rate) {
  return {.kind = DriveKind::Images,
          .rate_controlled = true,
          .shear_rate = rate,
          .size = Vec3(kLx, kLy, kLz)};
}

// gamma_dot = V / Lz; the power A V sigma_zx = sigma_zx gamma_dot times the
// volume A Lz, here with the measured stress, whatever the control.
TEST(ImageDrive, FeedsTheStressTimesTheRateTimesTheVolume) {
  const World w = box_at(0.25 * kLz);
  const ImageDrive drive(ImageDrive::control_for(rate_spec(0.25), 0.0));
  EXPECT_DOUBLE_EQ(drive.shear_rate(w), 0.25);
  const double sigma = 0.3, dt = 0.01;
  EXPECT_DOUBLE_EQ(drive.fed_work(w, sigma, dt) / dt, sigma * 0.25 * kLx * kLy * kLz);
}

// Stress control is the wall's equation of motion with the bulk stress for the
// contacts' force per area, M dV/dt = A (tau - sigma_zx); rate control keeps V.
TEST(ImageDrive, RespondsToTheMeasuredStress) {
  World w = box_at(0.7);
  ImageDrive stress(ImageDrive::control_for(stress_spec(3.0 / 20.0), 2.0));
  stress.respond(w, {.sigma_zx = 0.1}, 0.01);
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, 0.7 + 0.01 * (3.0 - 20.0 * 0.1) / 2.0);
  const double v = w.box.shear_velocity;
  stress.respond(w, {.sigma_zx = 3.0 / 20.0}, 0.01);  // the stress the drive applies: no change
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, v);
  ImageDrive rate(ImageDrive::control_for(rate_spec(0.25), 0.0));
  rate.respond(w, {.sigma_zx = 5.0}, 0.01);
  EXPECT_EQ(w.box.shear_velocity, 0.25 * kLz);
}

// Under stress control the drive alone accelerates the images at tau A / M and
// moves them by `reach` from rest at the bound; under rate control they move
// at V, and the bound is the time to cover `reach` at V.
TEST(ImageDrive, BoundsTheStepByTheImagesDisplacement) {
  const World w = box_at(1.5);
  const double reach = 0.02;
  const ImageDrive stress(ImageDrive::control_for(stress_spec(0.15), 2.0));
  const double dt = stress.time_step_bound(w, reach, kLz), a = 0.15 * kLx * kLy / 2.0;
  EXPECT_NEAR(0.5 * a * dt * dt, reach, 1e-15);
  const ImageDrive rate(ImageDrive::control_for(rate_spec(0.25), 0.0));
  EXPECT_DOUBLE_EQ(rate.time_step_bound(w, reach, kLz), reach / 1.5);
  // Relative to a neighbour a span s below, in the homogeneous shear: the
  // fraction s / Lz of the images' speed and acceleration.
  const double s = 0.25 * kLz;
  EXPECT_DOUBLE_EQ(rate.time_step_bound(w, reach, s), reach / (1.5 * 0.25));
  const double dt_s = stress.time_step_bound(w, reach, s);
  EXPECT_NEAR(0.5 * 0.25 * a * dt_s * dt_s, reach, 1e-15);
}

// No walls: no bodies and no block in the contact problem, the homogeneous
// flow about Lz/2, the bulk's normal stress, and the whole box is bulk.
TEST(ImageDrive, IsAWallFreeHomogeneousShear) {
  World w = box_at(1.2);
  ImageDrive drive(ImageDrive::control_for(stress_spec(0.1), 1.0));
  EXPECT_EQ(drive.contact_block(), nullptr);
  EXPECT_FALSE(drive.bounded_by_walls());
  EXPECT_EQ(drive.kinetic_energy(), 0.0);
  const ShearFlow flow = drive.mean_flow(w);
  EXPECT_DOUBLE_EQ(flow.shear_rate, 1.2 / kLz);
  EXPECT_EQ(flow.z0, 0.5 * kLz);
  EXPECT_EQ(drive.normal_stress(w, {}, -0.4), 0.4);
  const BulkRegion bulk = drive.bulk_region(w);
  EXPECT_TRUE(bulk.whole_box);
  EXPECT_EQ(bulk.z_hi, kLz);
}

// Continuation takes the next point's control (a rate imposed from the first
// step) and keeps the mass unless the spec names one; it refuses walls and
// another height.
TEST(ImageDrive, ContinuesUnderAnotherControlButNotAsAnotherCell) {
  World w = box_at(1.2);
  ImageDrive drive(ImageDrive::control_for(stress_spec(0.1), 3.0));
  DriveSpec walls = rate_spec(0.4);
  walls.kind = DriveKind::Walls;
  EXPECT_FALSE(drive.adopt(walls, w));
  DriveSpec taller = rate_spec(0.4);
  taller.size[2] = 2.0 * kLz;
  EXPECT_FALSE(drive.adopt(taller, w));
  EXPECT_EQ(w.box.shear_velocity, 1.2);
  ASSERT_TRUE(drive.adopt(rate_spec(0.4), w));
  EXPECT_EQ(w.box.shear_velocity, 0.4 * kLz);
  EXPECT_TRUE(drive.control().rate_controlled);
  EXPECT_EQ(drive.control().mass, 3.0);
}

// A checkpoint's record gives back the drive it came from.
TEST(ImageDrive, ComesBackFromItsRecord) {
  World w = box_at(1.2);
  w.bodies.add_sphere(0, Vec3(1.0, 1.0, 1.0), 0.5, 1.0, false);
  const ImageDrive drive(ImageDrive::control_for(stress_spec(0.1), 3.0));
  const DriveRecord record = drive.record(w);
  EXPECT_TRUE(record.owners.empty());
  EXPECT_TRUE(record.wall.spheres.empty());
  EXPECT_EQ(record.fault(w.box, 10), nullptr);
  World read = w;  // as a checkpoint reads it: bodies without motion or owner
  read.bodies.motion.clear();
  read.bodies.owner.clear();
  const auto back = restore_drive(record, read, {});
  EXPECT_EQ(read.bodies.motion, std::vector<Motion>{Motion::Dynamic});
  EXPECT_EQ(read.bodies.owner, std::vector<OwnerId>{kNoOwner});
  const auto* images = dynamic_cast<const ImageDrive*>(back.get());
  ASSERT_NE(images, nullptr);
  EXPECT_EQ(images->control().drive_force, drive.control().drive_force);
  EXPECT_EQ(images->control().mass, 3.0);
  DriveRecord massless = record;
  massless.images.mass = 0.0;
  EXPECT_STREQ(massless.fault(w.box, 10), "boundary mass");
}

}  // namespace
}  // namespace dilatant::image_drive_test
