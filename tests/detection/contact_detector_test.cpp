// The cell list must find exactly the pairs a brute-force O(N^2) search finds:
// every sphere pair (not both fixed) whose surfaces, at the nearest periodic
// image, are closer than the margin; and every mobile sphere near a plane.
// Gaps and normals are computed by the same formulas, so they must agree
// bit for bit.
#include "detection/contact_detector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace dilatant::contact_detector_test {
namespace {

struct Expected {
  int i, other;
  double gap;
  Vec3 normal;
};

std::vector<Expected> brute_force(const World& world, double margin) {
  const Bodies& b = world.bodies;
  std::vector<Expected> out;
  for (std::size_t i = 0; i < b.size(); ++i) {
    for (std::size_t j = i + 1; j < b.size(); ++j) {
      if (b.is_fixed(i) && b.is_fixed(j)) continue;
      const Vec3 d = world.box.minimum_image(b.position[i], b.position[j]);
      const double gap = d.norm() - b.radius[i] - b.radius[j];
      if (gap <= margin) {
        out.push_back({static_cast<int>(i), static_cast<int>(j), gap, d / d.norm()});
      }
    }
  }
  for (std::size_t k = 0; k < world.planes.size(); ++k) {
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (b.is_fixed(i)) continue;
      const double gap = world.planes[k].distance(b.position[i]) - b.radius[i];
      if (gap <= margin) {
        out.push_back({static_cast<int>(i), -static_cast<int>(k) - 1, gap, world.planes[k].normal});
      }
    }
  }
  return out;
}

// A few hundred polydisperse spheres (radii in [0.4, 1]) at random positions,
// periodic in x and y with box length L; some positions lie outside [0, L) to
// exercise the wrapping, a tenth are fixed, and two planes bound z.
World random_world(double length, int n, unsigned seed) {
  World world;
  world.box.length = Vec3(length, length, 0.0);
  world.box.periodic = {true, true, false};
  world.planes.push_back(Plane{Vec3(0.0, 0.0, 0.0), Vec3::UnitZ()});
  world.planes.push_back(Plane{Vec3(0.0, 0.0, 10.0), -Vec3::UnitZ()});
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const Vec3 x((1.2 * u(rng) - 0.1) * length, (1.2 * u(rng) - 0.1) * length, 10.0 * u(rng));
    world.bodies.add_sphere(k, x, 0.4 + 0.6 * u(rng), 1.0, k % 10 == 0);
  }
  return world;
}

void expect_same_as_brute_force(const World& world, double margin, int min_across_boundary) {
  ContactDetector detector;
  std::vector<Contact> found;
  detector.detect(world, margin, found);
  const std::vector<Expected> expected = brute_force(world, margin);

  // Deterministic order: sphere pairs by (i, j), then planes by (k, i).
  ASSERT_EQ(found.size(), expected.size());
  int across = 0;
  for (std::size_t n = 0; n < found.size(); ++n) {
    const Contact& c = found[n];
    const Expected& e = expected[n];
    SCOPED_TRACE(testing::Message() << "contact " << n << " (" << e.i << ", " << e.other << ")");
    ASSERT_EQ(c.i, e.i);
    ASSERT_EQ(c.other, e.other);
    EXPECT_EQ(c.gap, e.gap);
    EXPECT_EQ(c.normal, e.normal);
    if (c.other >= 0) {
      const Vec3 raw = world.bodies.position[c.i] - world.bodies.position[c.other];
      if ((raw -
           world.box.minimum_image(world.bodies.position[c.i], world.bodies.position[c.other]))
              .norm() > 1e-9) {
        ++across;
      }
      // Geometry for the solver: arms and Delassus coefficients.
      EXPECT_EQ(c.arm_i, world.bodies.radius[c.i]);
      EXPECT_EQ(c.arm_j, world.bodies.radius[c.other]);
    }
  }
  testing::Test::RecordProperty("contacts", static_cast<int>(found.size()));
  testing::Test::RecordProperty("pairs_across_boundary", across);
  // The scenes are built so that many pairs are found only through a periodic image.
  EXPECT_GE(across, min_across_boundary);
}

TEST(ContactDetector, MatchesBruteForceInALargePeriodicBox) {
  // 300 spheres, L = 12: cell size 2 r_max + margin = 2.1 gives 5 cells per axis.
  expect_same_as_brute_force(random_world(12.0, 300, 1), 0.1, 10);
  expect_same_as_brute_force(random_world(12.0, 300, 2), 0.1, 10);
}

TEST(ContactDetector, MatchesBruteForceWithTwoAndThreeCellsPerAxis) {
  // Few cells per periodic axis: a neighbour cell is reached from both sides
  // and must be visited once. L >= 2 (2 r_max + margin) keeps the minimum image
  // unique.
  expect_same_as_brute_force(random_world(5.0, 200, 3), 0.1, 10);  // 2 cells
  expect_same_as_brute_force(random_world(7.0, 200, 4), 0.1, 10);  // 3 cells
}

TEST(ContactDetector, LargeMarginAndFarFlungSphere) {
  // A generous margin (as after a fast step) and one sphere far out along the
  // non-periodic z axis, which caps the number of cells there.
  World world = random_world(12.0, 300, 5);
  world.bodies.add_sphere(999, Vec3(3.0, 3.0, 1e5), 0.5, 1.0, false);
  expect_same_as_brute_force(world, 0.7, 10);
}

TEST(ContactDetector, NonPeriodicBox) {
  World world = random_world(12.0, 300, 6);
  world.box.periodic = {false, false, false};
  expect_same_as_brute_force(world, 0.1, 0);
}

// Lees–Edwards (geometry/periodic_box.hpp): z periodic and the copies above
// and below displaced along x by an offset that falls anywhere, on a cell
// border or not. The cell list must still find every pair the sheared
// nearest image finds, with the image's velocity offset.
TEST(ContactDetector, MatchesBruteForceAcrossALeesEdwardsBoundary) {
  for (const double length : {12.0, 5.0, 7.0}) {
    for (const double offset : {0.0, 0.37, 2.1, 4.9999, 6.3}) {
      World world = random_world(length, length > 6.0 ? 300 : 150, 7);
      world.planes.clear();
      world.box.length[2] = 10.0;
      world.box.periodic = {true, true, true};
      world.box.lees_edwards = true;
      world.box.shear_offset = std::fmod(offset, length);
      world.box.shear_velocity = 0.75;
      SCOPED_TRACE(testing::Message() << "L " << length << ", offset " << offset);
      expect_same_as_brute_force(world, 0.1, 10);
      ContactDetector detector;
      std::vector<Contact> found;
      detector.detect(world, 0.1, found);
      int drifting = 0;
      for (const Contact& c : found) {
        const auto image =
            world.box.nearest_image(world.bodies.position[c.i], world.bodies.position[c.other]);
        EXPECT_EQ(c.image_drift, image.image * 0.75);
        drifting += image.image != 0;
      }
      EXPECT_GE(drifting, 5);
    }
  }
}

}  // namespace
}  // namespace dilatant::contact_detector_test
