#pragma once
// Everything the time stepper advances that is not a boundary: bodies, fixed
// planes, the box, and the external fields acting on them. What drives a cell
// from its edges (the shear cell's walls) is a Boundary (boundary/).
#include <vector>

#include "geometry/periodic_box.hpp"
#include "world/bodies.hpp"
#include "world/plane.hpp"

namespace dilatant {

struct World {
  Bodies bodies;
  std::vector<Plane> planes;
  PeriodicBox box;
  Vec3 gravity = Vec3::Zero();
  // Extra constant force on each body (e.g. a driving force); empty means none.
  std::vector<Vec3> external_force;
  double time = 0.0;
};

}  // namespace dilatant
