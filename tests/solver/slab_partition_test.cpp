// The red-black slab order of the parallel sweep: contacts of two slabs of the
// same colour never share a sphere that moves, whatever the packing.
#include "solver/slab_partition.hpp"

#include <gtest/gtest.h>

#include <set>

#include "boundary/wall_owner.hpp"
#include "detection/contact_detector.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "io/config.hpp"

namespace dilatant::slab_partition_test {
namespace {

struct DetectedCell {
  World world;
  RoughWalls walls;
  std::vector<Contact> contacts;
};

DetectedCell detected_cell(const std::vector<std::string>& overrides) {
  DetectedCell d;
  ShearCellGeometry geometry;
  d.world = build_shear_cell(default_cell_config(overrides), geometry, d.walls);
  ContactDetector detector;
  detector.detect(d.world, 0.1, d.contacts);
  return d;
}

std::set<int> moving_spheres(const World& world, const std::vector<Contact>& contacts,
                             std::size_t begin, std::size_t end) {
  std::set<int> spheres;
  for (std::size_t k = begin; k < end; ++k) {
    const Contact& c = contacts[k];
    if (!world.bodies.is_fixed(static_cast<std::size_t>(c.i))) spheres.insert(c.i);
    if (!c.with_plane() && !world.bodies.is_fixed(static_cast<std::size_t>(c.other))) {
      spheres.insert(c.other);
    }
  }
  return spheres;
}

TEST(SlabPartition, SlabsOfOneColourShareNoMovingSphere) {
  DetectedCell d = detected_cell({"cell.size=[10.0, 6.0, 27.0]", "cell.phi=0.58"});
  const std::size_t total = d.contacts.size();
  std::vector<Contact> scratch;
  const SlabPartition p = partition_into_slabs(d.contacts, d.world, scratch);
  ASSERT_EQ(p.count(), kMaxSlabs);  // 27 R holds 8 slabs of more than 2 reach
  ASSERT_EQ(d.contacts.size(), total);
  EXPECT_EQ(p.begin.front(), 0u);
  EXPECT_EQ(p.begin.back(), total);
  for (int a = 0; a < p.count(); ++a) {
    const auto sa = moving_spheres(d.world, d.contacts, p.begin[a], p.begin[a + 1]);
    for (int b = a + 2; b < p.count(); b += 2) {
      for (int s : moving_spheres(d.world, d.contacts, p.begin[b], p.begin[b + 1])) {
        EXPECT_EQ(sa.count(s), 0u) << "slabs " << a << " and " << b << " share sphere " << s;
      }
    }
  }
}

TEST(SlabPartition, WallContactsCloseEachSlabAndTopWallIsInTheLastSlab) {
  DetectedCell d = detected_cell({"cell.size=[10.0, 6.0, 27.0]", "cell.phi=0.58"});
  std::vector<Contact> scratch;
  const SlabPartition p = partition_into_slabs(d.contacts, d.world, scratch);
  for (int k = 0; k < p.count(); ++k) {
    for (std::size_t i = p.begin[k]; i < p.begin[k + 1]; ++i) {
      const Contact& c = d.contacts[i];
      const Bodies& b = d.world.bodies;
      const bool wall = b.is_driven(static_cast<std::size_t>(c.i)) ||
                        (!c.with_plane() && b.is_driven(static_cast<std::size_t>(c.other)));
      EXPECT_EQ(wall, i >= p.boundary_begin[k]);
      // The walls' block is solved while even slabs run: the top wall must be odd.
      const bool top =
          b.owner[c.i] == kTopWall || (!c.with_plane() && b.owner[c.other] == kTopWall);
      if (top) {
        EXPECT_EQ(k, p.count() - 1);
      }
    }
  }
}

TEST(SlabPartition, ThinCellsAndPeriodicAxesKeepOneSlab) {
  DetectedCell thin = detected_cell({"cell.size=[6.0, 5.0, 4.0]", "cell.phi=0.3"});
  std::vector<Contact> scratch;
  EXPECT_EQ(partition_into_slabs(thin.contacts, thin.world, scratch).count(), 1);
  DetectedCell d = detected_cell({"cell.size=[10.0, 6.0, 27.0]", "cell.phi=0.58"});
  d.world.box.periodic[2] = true;
  EXPECT_EQ(partition_into_slabs(d.contacts, d.world, scratch).count(), 1);
}

}  // namespace
}  // namespace dilatant::slab_partition_test
