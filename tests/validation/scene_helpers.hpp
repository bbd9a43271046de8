#pragma once
// Small builders and look-ups shared by the validation tests: a world with a
// floor, the mass of a sphere, and finding a contact of the last step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant::scenes {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

inline double sphere_mass(double r, double density = 1.0) {
  return 4.0 / 3.0 * std::numbers::pi * density * r * r * r;
}

// A world with one plane through `point` with unit normal `normal`.
inline World world_with_plane(const Vec3& gravity, const Vec3& point = Vec3::Zero(),
                              const Vec3& normal = Vec3::UnitZ()) {
  World w;
  w.gravity = gravity;
  w.planes.push_back(Plane{point, normal.normalized()});
  return w;
}

// The contact of sphere i with plane k in a list, or nullptr.
inline const Contact* find_plane_contact(const std::vector<Contact>& contacts, int i, int k = 0) {
  for (const Contact& c : contacts) {
    if (c.i == i && c.with_plane() && c.plane_index() == k) return &c;
  }
  return nullptr;
}

// The contact between spheres i and j (either order), or nullptr.
inline const Contact* find_pair_contact(const std::vector<Contact>& contacts, int i, int j) {
  for (const Contact& c : contacts) {
    if (c.with_plane()) continue;
    if ((c.i == i && c.other == j) || (c.i == j && c.other == i)) return &c;
  }
  return nullptr;
}

// Velocity of the lowest point of a sphere resting on a plane of normal n,
// relative to the plane: v - r w x n (zero when rolling without slip).
inline Vec3 contact_point_velocity(const Vec3& v, const Vec3& w, double r, const Vec3& n) {
  return v - r * w.cross(n);
}

// Records a measured number in the test's XML output (--gtest_output=xml), so
// that errors and their tolerances can be read without rerunning in a debugger.
inline void record(const std::string& key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  ::testing::Test::RecordProperty(key, text);
}

}  // namespace dilatant::scenes
