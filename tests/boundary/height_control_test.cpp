// The Lees–Edwards images under pressure control (boundary/image_drive.hpp):
// the box height H is a lid of mass M, M dW/dt = A (p - P), moved between
// steps by an affine dilation of z; the imposed rate keeps V = gamma_dot H.
// Hand-made worlds, exact arithmetic where the update is exact.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/drive_record.hpp"
#include "boundary/image_drive.hpp"

namespace dilatant::height_control_test {
namespace {

constexpr double kLx = 4.0, kLy = 5.0, kLz = 8.0;
constexpr double kArea = kLx * kLy;

DriveSpec pressure_spec(double rate, double p) {
  return {.kind = DriveKind::Images,
          .rate_controlled = true,
          .pressure_controlled = true,
          .shear_rate = rate,
          .normal_stress = p,
          .size = Vec3(kLx, kLy, kLz)};
}

World box_with_spheres(double rate) {
  World w;
  w.box.length = Vec3(kLx, kLy, kLz);
  w.box.periodic = {true, true, true};
  w.box.lees_edwards = true;
  w.box.shear_velocity = rate * kLz;
  w.box.shear_offset = 1.25;
  w.bodies.add_sphere(0, Vec3(1.0, 1.0, 0.5), 0.5, 1.0, false);
  w.bodies.add_sphere(1, Vec3(2.0, 3.0, 4.0), 0.5, 1.0, false);
  w.bodies.add_sphere(2, Vec3(3.5, 4.5, 7.75), 0.5, 1.0, false);
  return w;
}

// One response from rest: the step saw W = 0, so nothing dilates; the lid
// takes W = dt A (p - P) / M (no films: c = 0) and the box's dilation rate
// W / H for the next step's contacts. The next response dilates by the W that
// step saw: every z and Lz scaled by s = (H + W dt) / H; x, y, the velocities
// and the images' offset unchanged, V = gamma_dot H of the new height.
TEST(HeightControl, MovesTheHeightByTheStressImbalanceAndDilatesZ) {
  const double rate = 0.25, p_imposed = 2.0, mass = 10.0, dt = 0.01;
  World w = box_with_spheres(rate);
  w.bodies.velocity[1] = Vec3(0.3, -0.2, 0.1);
  const World before = w;
  ImageDrive drive(ImageDrive::control_for(pressure_spec(rate, p_imposed), mass));
  const double p_measured = 3.0;  // the flow pushes harder: the box grows
  drive.respond(w, {.sigma_zx = 0.7, .sigma_zz = -p_measured}, dt);
  const double speed = dt * kArea * (p_measured - p_imposed) / mass;
  EXPECT_DOUBLE_EQ(drive.control().height_speed, speed);
  EXPECT_EQ(w.box.length[2], kLz);
  EXPECT_EQ(w.bodies.position, before.bodies.position);
  EXPECT_DOUBLE_EQ(w.box.dilation_rate, speed / kLz);
  drive.respond(w, {.sigma_zx = 0.7, .sigma_zz = -p_imposed}, dt);  // balanced: W stays
  EXPECT_DOUBLE_EQ(drive.control().height_speed, speed);
  const double s = (kLz + speed * dt) / kLz;
  EXPECT_GT(s, 1.0);
  EXPECT_DOUBLE_EQ(w.box.length[2], kLz * s);
  EXPECT_DOUBLE_EQ(w.box.dilation_rate, speed / (kLz * s));
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    EXPECT_DOUBLE_EQ(w.bodies.position[i][2], before.bodies.position[i][2] * s);
    EXPECT_EQ(w.bodies.position[i][0], before.bodies.position[i][0]);
    EXPECT_EQ(w.bodies.position[i][1], before.bodies.position[i][1]);
    EXPECT_EQ(w.bodies.velocity[i], before.bodies.velocity[i]);
    EXPECT_LT(w.bodies.position[i][2], w.box.length[2]);  // still inside the box
  }
  EXPECT_EQ(w.box.length[0], kLx);
  EXPECT_EQ(w.box.shear_offset, before.box.shear_offset);
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, rate * w.box.length[2]);
  EXPECT_DOUBLE_EQ(drive.shear_rate(w), rate);
  // A lower measured pressure decelerates the lid, then shrinks the box.
  for (int n = 0; n < 5; ++n) drive.respond(w, {.sigma_zz = -1.0}, dt);
  EXPECT_LT(drive.control().height_speed, 0.0);
  EXPECT_LT(w.box.length[2], before.box.length[2] * s);
}

// With squeeze films the lid's speed is linearly implicit in their
// resistance c = -dp/dW (boundary/lid_resistance.hpp): W = dt A (p - P) /
// (M + dt A c). A stiff film (dt A c = 1000 M) makes it the overdamped
// piston's terminal speed (p - P) / c to 0.1%, where the explicit step would
// overshoot it a thousandfold.
TEST(HeightControl, TakesTheFilmsResistanceImplicitly) {
  const double p_imposed = 2.0, mass = 10.0, dt = 0.01, p_measured = 3.0;
  const double c = 1000.0 * mass / (dt * kArea);
  World w = box_with_spheres(0.25);
  ImageDrive drive(ImageDrive::control_for(pressure_spec(0.25, p_imposed), mass));
  drive.respond(w, {.sigma_zz = -p_measured, .lid_resistance = c}, dt);
  const double speed = drive.control().height_speed;
  EXPECT_DOUBLE_EQ(speed, dt * kArea * (p_measured - p_imposed) / (mass + dt * kArea * c));
  EXPECT_NEAR(speed, (p_measured - p_imposed) / c, 1e-3 * (p_measured - p_imposed) / c);
}

// Images stay images: after a dilation the separation of two bodies across the
// periodic z boundary is the dilated one, and the Lees–Edwards shift in x the
// same offset (the dilation moves no body out of the box).
TEST(HeightControl, KeepsImagesConsistentAcrossTheDilation) {
  World w = box_with_spheres(0.25);
  const PeriodicBox::Image across = w.box.nearest_image(w.bodies.position[2], w.bodies.position[0]);
  ASSERT_EQ(across.image, 1);  // 7.75 and 0.5 in a box of 8 meet through the top
  ImageDrive drive(ImageDrive::control_for(pressure_spec(0.25, 1.0), 1.0));
  drive.dilate(w, 1.1);
  const PeriodicBox::Image after = w.box.nearest_image(w.bodies.position[2], w.bodies.position[0]);
  EXPECT_EQ(after.image, 1);
  EXPECT_DOUBLE_EQ(after.d[2], 1.1 * across.d[2]);
  EXPECT_DOUBLE_EQ(after.d[0], across.d[0]);
  EXPECT_DOUBLE_EQ(after.d[1], across.d[1]);
}

// At the imposed pressure nothing moves: W stays 0, H and every z exactly.
TEST(HeightControl, StaysPutAtTheImposedPressure) {
  World w = box_with_spheres(0.5);
  const World before = w;
  ImageDrive drive(ImageDrive::control_for(pressure_spec(0.5, 2.0), 3.0));
  for (int n = 0; n < 10; ++n) drive.respond(w, {.sigma_zx = 0.4, .sigma_zz = -2.0}, 0.01);
  EXPECT_EQ(drive.control().height_speed, 0.0);
  EXPECT_EQ(w.box.length[2], kLz);
  EXPECT_EQ(w.bodies.position, before.bodies.position);
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, 0.5 * kLz);
}

// The lid alone: from rest it accelerates at P A / M, and the step bound lets
// it move by `reach` (the rate's bound, reach / V, when that is shorter); a
// lid already moving at W, by no more than `reach` at W.
TEST(HeightControl, BoundsTheStepByTheLidsDisplacement) {
  const World w = box_with_spheres(1e-6);  // a rate too slow to bound anything
  const double p = 2.0, mass = 5.0, reach = 0.02;
  ImageDrive drive(ImageDrive::control_for(pressure_spec(1e-6, p), mass));
  const double dt = drive.time_step_bound(w, reach, kLz);
  EXPECT_NEAR(0.5 * (p * kArea / mass) * dt * dt, reach, 1e-15);
  World moving = w;
  drive.respond(moving, {.sigma_zz = -(p + 100.0)}, 0.1);  // W = 0.1 * 20 * 100 / 5 = 40
  const double w_speed = drive.control().height_speed;
  EXPECT_DOUBLE_EQ(drive.time_step_bound(moving, reach, moving.box.length[2]), reach / w_speed);
  const ImageDrive fast(ImageDrive::control_for(pressure_spec(100.0, p), mass));
  World quick = box_with_spheres(100.0);
  EXPECT_DOUBLE_EQ(fast.time_step_bound(quick, reach, kLz), reach / (100.0 * kLz));
}

// Continuation under pressure control keeps the state's height, whatever it
// is, and the lid's speed; rate control still refuses another height.
TEST(HeightControl, ContinuesFromAnyHeight) {
  World w = box_with_spheres(0.25);
  ImageDrive drive(ImageDrive::control_for(pressure_spec(0.25, 2.0), 4.0));
  drive.respond(w, {.sigma_zz = -3.0}, 0.01);  // W from rest
  drive.respond(w, {.sigma_zz = -3.0}, 0.01);  // H moves by the W of the first
  const double h = w.box.length[2], speed = drive.control().height_speed;
  ASSERT_NE(h, kLz);
  ASSERT_TRUE(drive.adopt(pressure_spec(0.5, 1.0), w));
  EXPECT_EQ(w.box.length[2], h);
  EXPECT_EQ(drive.control().height_speed, speed);
  EXPECT_DOUBLE_EQ(w.box.dilation_rate, speed / h);
  EXPECT_DOUBLE_EQ(w.box.shear_velocity, 0.5 * h);
  EXPECT_EQ(drive.control().normal_force, 1.0 * kArea);
  DriveSpec rate = pressure_spec(0.5, 0.0);
  rate.pressure_controlled = false;
  EXPECT_FALSE(drive.adopt(rate, w));
}

// A checkpoint's record keeps the height's control; a pressure-controlled
// record without a mass is one no run wrote.
TEST(HeightControl, ComesBackFromItsRecord) {
  World w = box_with_spheres(0.25);
  ImageDrive drive(ImageDrive::control_for(pressure_spec(0.25, 2.0), 4.0));
  drive.respond(w, {.sigma_zz = -3.0}, 0.01);
  const DriveRecord record = drive.record(w);
  EXPECT_EQ(record.fault(w.box, w.bodies.size()), nullptr);
  w.box.dilation_rate = 0.0;  // a checkpoint keeps W, not the box's W / H
  const auto back = restore_drive(record, w, {});
  EXPECT_DOUBLE_EQ(w.box.dilation_rate, drive.control().height_speed / w.box.length[2]);
  EXPECT_NE(w.box.dilation_rate, 0.0);
  const auto* images = dynamic_cast<const ImageDrive*>(back.get());
  ASSERT_NE(images, nullptr);
  EXPECT_TRUE(images->control().pressure_controlled);
  EXPECT_EQ(images->control().height_speed, drive.control().height_speed);
  EXPECT_EQ(images->control().normal_force, 2.0 * kArea);
  DriveRecord massless = record;
  massless.images.mass = 0.0;
  EXPECT_STREQ(massless.fault(w.box, w.bodies.size()), "boundary mass");
}

}  // namespace
}  // namespace dilatant::height_control_test
